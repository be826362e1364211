#!/usr/bin/env python3
"""The launch files' arguments, as roslaunch itself sees them (test/launch_arguments.test).

* Every launch file loads with its required arguments, the nodes it starts exist and their
  packages are dependencies in package.xml (roslaunch's own check, roslaunch.rlutil, which
  roslaunch_add_file_check runs; that CMake macro cannot pass launch arguments, which
  replay.launch and hardware.launch require).
* `roslaunch --ros-args` (roslaunch.arg_dump) lists no argument as undocumented, and as required
  only those that are (replay.launch's bag; the actuators and their limits of hardware.launch,
  which every stack states; the drivers' actuators).
* Every argument a user can set reaches the file's check (scripts/check_launch_arguments.py),
  whose domains accept and refuse what the stacks do (a table of cases written from the launch
  files and the nodes' parameters).
* Bad values through a real `roslaunch` against this test's master: the launch stops, the first
  line on stderr names the argument, the value and what is allowed, and nothing was started: no
  node besides this test's, no parameter set.
"""
import importlib.util
import os
import re
import subprocess
import sys
import unittest
import xml.dom.minidom

import rosgraph
import rospy
import rostest
import roslaunch.arg_dump
import roslaunch.rlutil

PKG = 'spherical_robots'
SOURCE = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
LAUNCH = os.path.join(SOURCE, 'launch')
FIXTURE_BAG = os.path.join(SOURCE, 'test', 'data', 'terrain_3R_circle_fixture.bag')
HARDWARE_ARGS = ['actuators:=[a, b]', 'max_velocity:=1', 'max_acceleration:=1',
                 'command_timeout:=1', 'rate:=1']

# Every launch file with the arguments it requires (and nothing else).
REQUIRED = {
    'terrain_stack.launch': [],
    'roller_stack.launch': [],
    'norma_stack.launch': [],
    'rotor_stack.launch': [],
    'freebot_stack.launch': [],
    'record.launch': [],
    'replay.launch': ['bag:=' + FIXTURE_BAG],
    'hardware.launch': HARDWARE_ARGS,
    'hardware/sim.launch': ['actuators:=[a, b]'],
    'hardware/loopback.launch': ['actuators:=[a, b]'],
}

# (launch file, arguments, first line on stderr)
BAD_VALUES = [
    ('terrain_stack.launch', ['robot:=4R'],
     "argument 'robot' = '4R': expected one of 3R, 2R, RT, RS"),
    ('terrain_stack.launch', ['speedup:=-1'],
     "argument 'speedup' = '-1': expected a number >= 0 [x real time]"),
    ('terrain_stack.launch', ['duration:=-5'],
     "argument 'duration' = '-5': expected a number >= 0 [s, simulated; 0 = forever]"),
    ('rotor_stack.launch', ['target:=abc'],
     "argument 'target' = 'abc': expected u,v,psi: three numbers [m, m, rad], e.g. 0.05,0.03,0.4"),
    ('rotor_stack.launch', ['corrections:=two'],
     "argument 'corrections' = 'two': expected a whole number >= 0"),
    ('freebot_stack.launch', ['modules:=3', 'radii:=[0.04, 0.034]'],
     "argument 'radii' = '[0.04, 0.034]': expected none or a list of modules + 1 radii > 0 [m], "
     'e.g. "[0.04, 0.034, 0.034, 0.034, 0.034]"'),
    ('roller_stack.launch', ['actuator_models:=/no/such/models.yaml'],
     "argument 'actuator_models' = '/no/such/models.yaml': expected none or a YAML file of "
     'actuator models (an existing file)'),
]


# (launch file, NAME=VALUE..., the arguments outside their domain): what the stacks accept.
DOMAIN_CASES = [
    ('terrain_stack', ['robot=RS', 'path=diamond', 'model=rolling', 'law=paper'], []),
    ('terrain_stack', ['rviz=True', 'nodelet=0', 'owns_clock=false'], []),
    ('terrain_stack', ['respawn=true'], []),
    ('norma_stack', ['respawn=sometimes'], ['respawn']),
    ('terrain_stack', ['rviz=yes', 'ns=1sphere', 'frame_prefix=sphere'],
     ['rviz', 'ns', 'frame_prefix']),
    ('terrain_stack', ['clock=lockstep', 'speedup=0'], []),
    ('terrain_stack', ['clock=free', 'speedup=0'], ['speedup']),  # 0 would stop free time
    ('terrain_stack', ['speedup=nan', 'duration=inf'], ['speedup', 'duration']),
    ('terrain_stack', ['record=none', 'clock_leader=/sphere', 'clock_followers=/a/b,/c/d'], []),
    ('terrain_stack', ['record=run.bag', 'clock_leader=sphere', 'clock_followers=a/b'],
     ['clock_leader', 'clock_followers']),
    ('terrain_stack', ['record=', 'hardware=loopback', 'actuator_models=' + __file__],
     ['record', 'actuator_models']),
    ('terrain_stack', ['hardware=sim', 'actuator_models=' + __file__], []),
    ('terrain_stack', ['hardware=none', 'wait_for_subscribers=2'], []),
    ('terrain_stack', ['part=robot', 'nodelet=false'], []),
    ('terrain_stack', ['loop_cpu=auto'], []),
    ('norma_stack', ['loop_cpu=none'], []),
    ('rotor_stack', ['loop_cpu=%d' % min(os.sched_getaffinity(0))], []),
    ('roller_stack', ['loop_cpu=%d' % (max(os.sched_getaffinity(0)) + 1)], ['loop_cpu']),
    ('freebot_stack', ['loop_cpu=-1'], ['loop_cpu']),
    ('terrain_stack', ['loop_cpu=fastest'], ['loop_cpu']),
    ('terrain_stack', ['part=workstation', 'nodelet=true'], ['part']),
    ('terrain_stack', ['part=controller'], ['part']),
    ('terrain_stack', ['hardware=robot', 'wait_for_subscribers=1.5'],
     ['hardware', 'wait_for_subscribers']),
    ('rotor_stack', ['steps=0', 'corrections=-1', 'k=0', 'target=1,2'],
     ['steps', 'corrections', 'k', 'target']),
    ('rotor_stack', ['steps=3', 'corrections=2', 'k=2.5', 'target=-0.1,2e-2,7'], []),
    ('freebot_stack', ['modules=2', 'radii=[0.04, 0.03, 0.03]'], []),
    ('freebot_stack', ['modules=2', 'radii=[0.04, 0.03, 0.03, 0.03]'], ['radii']),
    ('freebot_stack', ['modules=2', 'radii=[0.04, -0.03, 0.03]'], ['radii']),
    ('record', ['robot=k2.5', 'bag=none', 'compression=lz4'], []),
    ('record', ['bag=/no/such/dir/x.bag', 'compression=gzip'], ['bag', 'compression']),
    ('replay', ['bag=' + FIXTURE_BAG, 'topics=/sphere/odom /tf', 'rate=4', 'rviz_frame_rate=10'],
     []),
    ('replay', ['bag=' + FIXTURE_BAG, 'rviz_frame_rate=none'], []),
    ('replay', ['bag=test/data/x.bag', 'topics=odom', 'rate=0', 'rviz_frame_rate=0'],
     ['bag', 'topics', 'rate', 'rviz_frame_rate']),
    ('replay', ['bag=' + FIXTURE_BAG, 'rviz_frame_rate=fast'], ['rviz_frame_rate']),
    ('hardware', ['hardware=loopback', 'actuators=[a, b]', 'effort_limits={a: 2}'], []),
    ('hardware', ['hardware=none', 'actuators=a', 'effort_limits=[2]'],
     ['hardware', 'actuators', 'effort_limits']),
    ('hardware/loopback', ['models=none', 'manager=none'], []),
    ('hardware/loopback', ['models=' + __file__], ['models']),
]


def checker():
    """scripts/check_launch_arguments.py as a module."""
    path = os.path.join(SOURCE, 'scripts', 'check_launch_arguments.py')
    spec = importlib.util.spec_from_file_location('check_launch_arguments', path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def launch_path(name):
    return os.path.join(LAUNCH, name)


def user_arguments(name):
    """The <arg>s a user can set (default= or required, not value=) and the words of the
    file's check command."""
    dom = xml.dom.minidom.parse(launch_path(name))
    launch = dom.documentElement
    args = [a.getAttribute('name') for a in launch.getElementsByTagName('arg')
            if a.parentNode is launch and not a.hasAttribute('value')]
    checks = [p.getAttribute('command') for p in launch.getElementsByTagName('param')
              if 'check_launch_arguments.py' in p.getAttribute('command')]
    return args, checks


class LaunchArguments(unittest.TestCase):

    def test_every_launch_file_is_listed(self):
        found = {os.path.relpath(os.path.join(d, f), LAUNCH)
                 for d, _, files in os.walk(LAUNCH) for f in files if f.endswith('.launch')}
        self.assertEqual(found, set(REQUIRED))

    def test_domains(self):
        check = checker()
        problems = []
        for launch, words, expected in DOMAIN_CASES:
            arguments = dict(w.split('=', 1) for w in words)
            found = [name for name, _, _ in check.problems(launch, arguments)]
            if found != expected:
                problems.append('%s %s: outside %s, expected %s' % (launch, words, found, expected))
        self.assertFalse(problems, '\n'.join(problems))

    def test_each_loads_with_its_required_arguments(self):
        errors = []
        saved = sys.argv
        try:
            for name, args in sorted(REQUIRED.items()):
                sys.argv = ['roslaunch-check'] + args  # where roslaunch's loader reads them
                error = roslaunch.rlutil.check_roslaunch(launch_path(name))
                if error:
                    errors.append('%s %s: %s' % (name, ' '.join(args), error))
        finally:
            sys.argv = saved
        self.assertFalse(errors, '\n'.join(errors))

    def test_ros_args_documented_and_required_only_where_required(self):
        problems = []
        for name, args in sorted(REQUIRED.items()):
            listed = roslaunch.arg_dump.get_args([launch_path(name)])
            undocumented = sorted(n for n, (doc, _) in listed.items() if not doc)
            required = sorted(n for n, (_, default) in listed.items() if not default)
            if undocumented:
                problems.append('%s: undocumented %s' % (name, undocumented))
            if required != sorted(a.split(':=')[0] for a in args):
                problems.append('%s: required %s' % (name, required))
        self.assertFalse(problems, '\n'.join(problems))

    def test_every_user_argument_is_checked(self):
        problems = []
        for name in sorted(REQUIRED):
            args, checks = user_arguments(name)
            if len(checks) != 1:
                problems.append('%s: %d checks' % (name, len(checks)))
                continue
            checked = re.findall(r"'([a-z_]+)=\$\(arg \1\)'", checks[0])
            if checked != args or ' %s ' % name[:-len('.launch')] not in checks[0]:
                problems.append('%s: arguments %s, checked %s' % (name, args, checked))
        self.assertFalse(problems, '\n'.join(problems))

    def test_bad_values_stop_the_launch_before_anything_starts(self):
        master = rosgraph.Master('/launch_arguments_check')
        nodes_before = self.nodes(master)
        params_before = set(master.getParamNames())
        problems = []
        for name, args, first_line in BAD_VALUES:
            case = 'roslaunch %s %s' % (name, ' '.join(args))
            # By path: the test's environment has the package in the source tree and installed.
            result = subprocess.run(['roslaunch', launch_path(name)] + args, capture_output=True,
                                    text=True, timeout=120, stdin=subprocess.DEVNULL)
            lines = result.stderr.splitlines()
            if result.returncode == 0 or not lines or lines[0] != first_line:
                problems.append('%s: exit %d, stderr:\n%s'
                                % (case, result.returncode, result.stderr))
            if 'process[' in result.stdout:
                problems.append('%s started a process:\n%s' % (case, result.stdout))
            if self.nodes(master) != nodes_before or set(master.getParamNames()) != params_before:
                problems.append('%s: nodes or parameters changed' % case)
        self.assertFalse(problems, '\n'.join(problems))

    @staticmethod
    def nodes(master):
        publishers, subscribers, services = master.getSystemState()
        return {n for _, names in publishers + subscribers + services for n in names}


if __name__ == '__main__':
    rospy.init_node('launch_arguments_check')
    rostest.rosrun(PKG, 'launch_arguments_check', LaunchArguments)
