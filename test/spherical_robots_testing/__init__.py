"""What the package's test programs share (test/*_check.py): a topic recorder that notes each
message's simulated arrival time, and waits on conditions, on simulated time and on an action
goal's end, each bounded by a wall-clock deadline so that a stack that never gets there fails the
test instead of hanging it; and, for the programs that launch stacks on masters of their own, a
free port and a launch file's path.

Not installed: it sits beside the test programs, which run from the package's source tree (the
directory of the running program is on Python's path).
"""
import contextlib
import math
import os
import signal
import socket
import threading
import time
import xmlrpc.client

import rosgraph
import rospkg
import rospy

__all__ = ['Recorder', 'wait_until', 'sim_sleep', 'GoalClient', 'publish_until', 'first_at_rest',
           'quaternion_angle', 'free_port', 'launch_file', 'node_uri', 'pid_of', 'silenced']

PKG = 'spherical_robots'


class Recorder:
    """Keeps every message of a topic, with the simulated time it arrived."""

    def __init__(self, topic, msg_type):
        self.lock = threading.Lock()
        self.messages = []
        self.subscriber = rospy.Subscriber(topic, msg_type, self.callback, queue_size=1000)

    def callback(self, msg):
        with self.lock:
            self.messages.append((rospy.Time.now().to_sec(), msg))

    def count(self):
        with self.lock:
            return len(self.messages)

    def last(self):
        with self.lock:
            return self.messages[-1][1] if self.messages else None

    def since(self, index):
        with self.lock:
            return [msg for _, msg in self.messages[index:]]

    def timed_since(self, t):
        """(arrival time, message) pairs that arrived at simulated time t or later."""
        with self.lock:
            return [(at, msg) for at, msg in self.messages if at >= t]


def wait_until(condition, what, timeout):
    """Polls condition every 0.05 s (wall) until it holds. @throw AssertionError naming `what`
    after `timeout` [s] of wall time, or when the node shuts down."""
    deadline = time.time() + timeout
    while not condition():
        if time.time() > deadline or rospy.is_shutdown():
            raise AssertionError('timed out after %.0f s (wall) waiting for %s' % (timeout, what))
        time.sleep(0.05)


def sim_sleep(seconds, timeout):
    """Sleeps `seconds` of simulated time, bounded by `timeout` [s] of wall time."""
    end = rospy.Time.now().to_sec() + seconds
    wait_until(lambda: rospy.Time.now().to_sec() >= end, '%.1f s of simulated time' % seconds,
               timeout)


class GoalClient:
    """An actionlib SimpleActionClient of one action server that keeps its goal's feedback; its
    waits are bounded by `timeout` [s] of wall time (the client's own count simulated time)."""

    def __init__(self, name, action_type, timeout):
        import actionlib  # only the action tests need it
        self.done_state = actionlib.SimpleGoalState.DONE
        self.client = actionlib.SimpleActionClient(name, action_type)
        self.timeout = timeout
        self.feedback = []
        # Connected both ways, or a goal sent now could be lost (simulated time flows meanwhile).
        wait_until(lambda: self.client.wait_for_server(rospy.Duration(0.1)),
                   'the %s action server' % name, timeout)

    def send(self, goal):
        self.feedback = []
        self.client.send_goal(goal, feedback_cb=self.feedback.append)

    def done(self):
        """Whether the goal has ended (its result received)."""
        return self.client.simple_state == self.done_state

    def result(self, what):
        """(actionlib_msgs/GoalStatus state, result) once the goal has ended."""
        wait_until(self.done, what, self.timeout)
        return self.client.get_state(), self.client.get_result()

    def state(self):
        return self.client.get_state()

    def cancel(self):
        self.client.cancel_goal()


def publish_until(publisher, messages, condition, what, timeout):
    """Publishes the messages every 0.2 s (wall) until condition holds, at most `timeout` [s] of
    wall time. For bad messages the node under test only counts: a test node that also
    subscribes to the topic cannot tell from get_num_connections() whether that node is
    connected yet, so it repeats until the node reports them."""
    deadline = time.time() + timeout
    while not condition():
        if time.time() > deadline or rospy.is_shutdown():
            raise AssertionError('timed out after %.0f s (wall) waiting for %s' % (timeout, what))
        for msg in messages:
            publisher.publish(msg)
        time.sleep(0.2)


def first_at_rest(states, t):
    """The first JointState a Recorder of actuators/state holds that is stamped at or after
    simulated time t with every velocity exactly 0 (what a watchdog or an e-stop sends), or None."""
    for _, msg in states.timed_since(t):
        if msg.header.stamp.to_sec() >= t and all(v == 0.0 for v in msg.velocity):
            return msg
    return None


def quaternion_angle(a, b):
    """The angle [rad] between the orientations of two quaternions given as (w, x, y, z), which
    need not be normalised."""
    na = math.sqrt(sum(c * c for c in a))
    nb = math.sqrt(sum(c * c for c in b))
    dot = abs(sum(x * y for x, y in zip(a, b))) / (na * nb)
    return 2.0 * math.acos(min(1.0, dot))


def free_port():
    """A TCP port nobody listens on now, for a ROS master of the caller's own."""
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


def launch_file(name):
    """The package's launch file by its full path, as $(find) resolves it. `roslaunch PKG FILE`
    searches the whole package directory, and when the package's path is its source tree with the
    colcon workspace inside it (under colcon test) it finds the installed copy too and refuses:
    "multiple files named [terrain_stack.launch]"."""
    return os.path.join(rospkg.RosPack().get_path(PKG), 'launch', name)


def node_uri(name, master_uri=None):
    """The URI the master (this node's, or the one at master_uri) has for node `name`, or None:
    a node killed and restarted by roslaunch (respawn) comes back under a new one."""
    try:
        return rosgraph.Master('/spherical_robots_testing', master_uri=master_uri).lookupNode(name)
    except (rosgraph.MasterError, OSError):
        return None


def pid_of(name, master_uri=None):
    """The pid of the process registered as node `name` (on this machine), or None."""
    uri = node_uri(name, master_uri)
    try:
        return uri and xmlrpc.client.ServerProxy(uri).getPid('/spherical_robots_testing')[2]
    except (OSError, xmlrpc.client.Error):
        return None


@contextlib.contextmanager
def silenced(name):
    """Node `name` stopped (SIGSTOP) for the block, continued (SIGCONT) after it: a participant
    that goes silent without dying, which neither ends the stack nor is restarted (a death ends
    it, or with respawn:=true roslaunch restarts it: docs/conventions.md, "When a node dies")."""
    pid = pid_of(name)
    if pid is None:
        raise AssertionError('no process for node %s' % name)
    os.kill(pid, signal.SIGSTOP)
    try:
        yield pid
    finally:
        os.kill(pid, signal.SIGCONT)
