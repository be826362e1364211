#!/usr/bin/env python3
"""scripts/run_stack.py's StackEnd, with deaths and times as plain numbers (test/stack_end.test):
which deaths end a stack, and whether normally (status 0) or as a failure (status 1). The cases
are the launch files' roles (docs/conventions.md, "When a node dies"). And one launch run through
run_stack.py on a master of its own: a node that cannot be started is a failed launch (status 2),
not a wait for ever."""
import importlib.util
import os
import subprocess
import sys
import tempfile
import unittest

import rosunit

from spherical_robots_testing import free_port

SOURCE = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))


def run_stack():
    spec = importlib.util.spec_from_file_location(
        'run_stack', os.path.join(SOURCE, 'scripts', 'run_stack.py'))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


RUN_STACK = run_stack()
PROCESSES = ['sphere/terrain_plant', 'sphere/pure_pursuit_controller', 'sphere/hardware_interface']
NODELETS = ['sphere/nodelet_manager'] + PROCESSES
SETTLE = 3.0


def stack_end(required):
    return RUN_STACK.StackEnd(required, RUN_STACK.ends_stack, settle=SETTLE)


class StackEndTest(unittest.TestCase):

    def test_the_plant_ends_the_stack_normally_at_once(self):
        end = stack_end(PROCESSES)
        self.assertIsNone(end.decide(10.0))
        end.died('sphere/terrain_plant', 0, 10.0)
        self.assertEqual(end.decide(10.0), 0)

    def test_a_killed_controller_is_a_failure_once_no_normal_end_followed(self):
        end = stack_end(PROCESSES)
        end.died('sphere/pure_pursuit_controller', -9, 10.0)
        self.assertIsNone(end.decide(10.0 + SETTLE / 2))
        self.assertEqual(end.decide(10.0 + SETTLE), 1)
        self.assertEqual(end.failures, [('sphere/pure_pursuit_controller', -9)])

    def test_a_controller_that_exits_cleanly_is_a_failure_too(self):
        # e.g. `rosnode kill`, or another node registered under its name
        end = stack_end(PROCESSES)
        end.died('sphere/pure_pursuit_controller', 0, 10.0)
        self.assertEqual(end.decide(10.0 + SETTLE), 1)

    def test_a_killed_plant_that_keeps_a_checkpoint_is_restarted_and_ends_the_stack_later(self):
        end = RUN_STACK.StackEnd(PROCESSES, RUN_STACK.ends_stack, 0.0,
                                 restarted=['sphere/terrain_plant'])
        end.died('sphere/terrain_plant', -9, 10.0)
        self.assertIsNone(end.decide(20.0))
        end.died('sphere/terrain_plant', 0, 30.0)
        self.assertEqual(end.decide(30.0), 0)

    def test_a_plant_that_keeps_a_checkpoint_and_exits_with_an_error_fails(self):
        # e.g. a bad parameter: restarting it would fail again
        end = RUN_STACK.StackEnd(PROCESSES, RUN_STACK.ends_stack, 0.0,
                                 restarted=['sphere/terrain_plant'])
        end.died('sphere/terrain_plant', 1, 10.0)
        self.assertEqual(end.decide(10.0), 1)

    def test_a_failed_plant_is_a_failure_at_once(self):
        end = stack_end(PROCESSES)
        end.died('sphere/terrain_plant', 1, 10.0)
        self.assertEqual(end.decide(10.0), 1)
        end = stack_end(PROCESSES)
        end.died('sphere/terrain_plant', -11, 10.0)
        self.assertEqual(end.decide(10.0), 1)

    def test_a_nodelet_stack_ends_normally_whatever_order_its_processes_end_in(self):
        # the plant shuts its manager down; the loaders end with it, before or after it
        end = stack_end(NODELETS)
        end.died('sphere/pure_pursuit_controller', 0, 10.0)
        end.died('sphere/hardware_interface', 0, 10.1)
        self.assertIsNone(end.decide(10.2))
        end.died('sphere/nodelet_manager', 0, 10.4)
        self.assertEqual(end.decide(10.4), 0)
        end.died('sphere/terrain_plant', 0, 10.5)
        self.assertEqual(end.decide(20.0), 0)

    def test_deaths_of_nodes_not_required_end_nothing(self):
        # observers, and with respawn:=true the loop's nodes, which roslaunch restarts
        end = stack_end(['sphere/terrain_plant'])
        end.died('sphere/robot_state_publisher', -9, 10.0)
        end.died('sphere/pure_pursuit_controller', -9, 11.0)
        end.died('sphere/pure_pursuit_controller', -9, 12.0)
        self.assertIsNone(end.decide(100.0))
        end.died('sphere/terrain_plant', 0, 120.0)
        self.assertEqual(end.decide(120.0), 0)

    def test_the_first_verdict_stands(self):
        end = stack_end(PROCESSES)
        end.died('sphere/terrain_plant', 0, 10.0)
        end.died('sphere/hardware_interface', -9, 10.1)
        self.assertEqual(end.decide(20.0), 0)


class RunStackTest(unittest.TestCase):

    def test_a_node_that_cannot_be_started_fails_the_launch(self):
        # Seen when a stack was launched while its package was being rebuilt: roslaunch logged
        # "cannot launch node" and run_stack.py waited for its death for ever.
        with tempfile.TemporaryDirectory() as home:
            launch = os.path.join(home, 'missing.launch')
            with open(launch, 'w') as f:
                f.write('<launch><node pkg="spherical_robots" type="no_such_node" '
                        'name="plant" required="true"/></launch>')
            result = subprocess.run(
                [sys.executable, os.path.join(SOURCE, 'scripts', 'run_stack.py'), '--port',
                 str(free_port()), launch], env=dict(os.environ, ROS_HOME=home),
                capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
        self.assertIn('could not be started', result.stderr)


if __name__ == '__main__':
    rosunit.unitrun('spherical_robots', 'stack_end', '__main__')  # both test cases
