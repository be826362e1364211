#!/usr/bin/env python3
"""roslaunch for a stack, with an exit status that says how it ended.

    rosrun spherical_robots run_stack.py terrain_stack.launch robot:=RS duration:=60
    rosrun spherical_robots run_stack.py --port 11312 norma_stack.launch respawn:=true

It launches the file (a launch file of the package, or a path) as roslaunch does, with roslaunch's
own API (roslaunch.parent.ROSLaunchParent, starting a master on --port or ROS_MASTER_URI's if none
runs), and watches every process's exit. The launch file says what each node is: its plant is
`required` (named *_plant, or the stack's nodelet_manager with nodelet:=true), and so are the other
nodes of the loop with respawn:=false; with respawn:=true those are `respawn` (roslaunch restarts
them); observers (rviz, the recorder, robot_state_publisher) are neither. Here, unlike roslaunch,
the end of a required process is sorted into a normal end or a failure (StackEnd), so a normal end
prints no red "REQUIRED process has died" and a failure gives a non-zero status. A plant that
keeps a checkpoint (its ~checkpoint is not `none`: the stacks' respawn:=true) is restarted when a
signal kills it, and resumes from its checkpoint; an exit with an error status still fails.

Exit status: 0 the plant ended the stack (it exits 0 at its `duration`); 1 a required node died
(a node of the loop with respawn:=false, or the plant failed); 2 the launch failed (bad arguments,
a missing file, a node that could not be started); 130 interrupted (Ctrl-C) before the stack ended.
"""
import argparse
import os
import queue
import signal
import sys
import time

import rosgraph.names
import roslaunch
import roslaunch.parent
import roslaunch.pmon
import roslaunch.rlutil
import rospkg

PKG = 'spherical_robots'
# At a normal end of a nodelet stack the plant shuts its manager down, and the loaders of the
# other nodelets end with it, in any order: there a death is a failure once no normal end has
# followed it within this many seconds of wall time. A stack of processes ends with its plant
# alone, so any other death there is a failure at once.
SETTLE = 3.0


class StackEnd:
    """Decides from the deaths of a stack's processes whether and how the stack ends.

    `required`: the node names (as roslaunch names processes: 'sphere/terrain_plant') whose end
    ends the stack; `ends_stack(node)`: whether that node ends it normally by exiting with
    status 0; `restarted`: required nodes that roslaunch restarts when a signal kills them.
    Times are seconds (any monotonic clock)."""

    def __init__(self, required, ends_stack, settle, restarted=()):
        self.required, self.ends_stack, self.settle = set(required), ends_stack, settle
        self.restarted = set(restarted)
        self.first_failure = None
        self.failures = []
        self.status = None

    def died(self, node, exit_code, now):
        """A process of `node` exited with `exit_code` (negative: the signal that killed it)."""
        if self.status is not None or node not in self.required:
            return  # respawned by roslaunch, or an observer
        if self.ends_stack(node) and exit_code == 0:
            self.status = 0
            return
        if node in self.restarted and exit_code < 0:
            return  # killed: restarted from its checkpoint
        self.failures.append((node, exit_code))
        if self.first_failure is None:
            self.first_failure = now

    def decide(self, now):
        """The stack's exit status once it is known at `now`, else None."""
        if self.status is None and self.first_failure is not None and (
                now - self.first_failure >= self.settle
                or any(self.ends_stack(node) for node, _ in self.failures)):
            self.status = 1
        return self.status


def ends_stack(node):
    """The plant, or the nodelet manager it runs in (it shuts the manager down at its end)."""
    name = node.rsplit('/', 1)[-1]
    return name.endswith('_plant') or name == 'nodelet_manager'


class Deaths(roslaunch.pmon.ProcessListener):
    def __init__(self):
        self.queue = queue.Queue()

    def process_died(self, process_name, exit_code):
        # roslaunch names a process NODE-COUNTER ('sphere/terrain_plant-3')
        self.queue.put((process_name.rsplit('-', 1)[0], exit_code))


class SupervisedLaunch(roslaunch.parent.ROSLaunchParent):
    """ROSLaunchParent that takes `required` over from roslaunch (which ends the launch on any
    required death, in red, with status 0) and tells `deaths` of every exit from the first."""

    def __init__(self, run_id, files, deaths, **kwargs):
        super().__init__(run_id, files, **kwargs)
        self.deaths = deaths
        self.failed_to_start = []
        self.required = []
        self.restarted = []

    def _load_config(self):
        super()._load_config()
        for node in self.config.nodes:
            if node.required:
                name = rosgraph.names.ns_join(node.namespace, node.name).lstrip('/')
                self.required.append(name)
                node.required = False
                checkpoint = self.config.params.get('/%s/checkpoint' % name)
                if checkpoint is not None and checkpoint.value != 'none':
                    self.restarted.append(name)
                    node.respawn = True

    def _start_pm(self):
        super()._start_pm()
        self.pm.add_process_listener(self.deaths)

    def _init_runner(self):
        # roslaunch logs a node it cannot start (an executable that is not there) and goes on:
        # that node never dies, so the stack would wait for it for ever. Count them here.
        super()._init_runner()
        launch = self.runner.launch

        def launch_and_count():
            succeeded, failed = launch()
            self.failed_to_start = failed
            return succeeded, failed
        self.runner.launch = launch_and_count


def launch_file(name):
    if os.path.isfile(name):
        return name
    return os.path.join(rospkg.RosPack().get_path(PKG), 'launch', name)


def report(status, failures):
    if status == 0:
        roslaunch.core.printlog('run_stack.py: the plant ended the stack normally')
    else:
        roslaunch.core.printerrlog('run_stack.py: the stack failed: ' + ', '.join(
            '%s %s' % (node, 'killed by signal %d' % -code if code < 0 else 'exited with %d' % code)
            for node, code in failures))


def main(argv):
    parser = argparse.ArgumentParser(
        description=__doc__.split('\n\n')[0],
        usage='run_stack.py [--port PORT] LAUNCH_FILE [NAME:=VALUE ...]')
    parser.add_argument('--port', type=int, help="the master's port (default: ROS_MASTER_URI's)")
    parser.add_argument('launch_file')
    parser.add_argument('arguments', nargs='*')
    args = parser.parse_args(argv)

    files = roslaunch.rlutil.resolve_launch_arguments([launch_file(args.launch_file)])
    # roslaunch reads NAME:=VALUE from sys.argv, as when run from its command line
    sys.argv = [sys.argv[0]] + args.arguments
    run_id = roslaunch.rlutil.get_or_generate_uuid(None, False)
    roslaunch.configure_logging(run_id)
    deaths = Deaths()
    parent = SupervisedLaunch(run_id, files, deaths, port=args.port)
    try:
        parent.start()
    except (roslaunch.core.RLException, ValueError, rospkg.ResourceNotFound) as error:
        roslaunch.core.printerrlog(str(error))
        parent.shutdown()
        return 2
    if parent.failed_to_start:
        roslaunch.core.printerrlog('run_stack.py: the launch failed: %d node(s) could not be '
                                   'started (above)' % len(parent.failed_to_start))
        parent.shutdown()
        return 2
    nodelets = any(node.rsplit('/', 1)[-1] == 'nodelet_manager' for node in parent.required)
    end = StackEnd(parent.required, ends_stack, SETTLE if nodelets else 0.0, parent.restarted)
    interrupted = []
    # Ctrl-C reaches the nodes too, and a plant that exits 0 on it has not ended the stack.
    roslaunch_handler = signal.getsignal(signal.SIGINT)

    def on_interrupt(signum, frame):
        interrupted.append(signum)
        if callable(roslaunch_handler):
            roslaunch_handler(signum, frame)
    signal.signal(signal.SIGINT, on_interrupt)
    try:
        running = True
        while running and not interrupted and end.decide(time.monotonic()) is None:
            running = parent.runner.spin_once()
            try:
                while True:
                    end.died(*deaths.queue.get(timeout=0.1), time.monotonic())
            except queue.Empty:
                pass
        if interrupted or end.decide(time.monotonic() + end.settle) is None:
            return 130
        report(end.status, end.failures)
        return end.status
    finally:
        parent.shutdown()


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
