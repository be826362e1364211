#!/usr/bin/env python3
"""Two hosts and a cut link (issue 18): the terrain stack split over two network namespaces,
the link between them cut mid-run and restored.

usage (as root, after `. install/setup.sh`):
    test/two_hosts_cut_link.py [--cut SECONDS] [--master robot|workstation] [--junit RESULT.xml]

Two namespaces joined by a veth pair stand for two computers: `robot` (10.210.0.1: the master,
unless --master workstation; `terrain_stack.launch part:=robot`, i.e. the plant and
hardware_interface_sim) and `workstation` (10.210.0.2: `part:=workstation`, the controller, and
an operator's `rostopic pub` of a 1 m/s teleop cmd_vel at 20 Hz), ROS_IP set in each,
clock:=wall as in hardware in the loop. An observer in the robot's namespace (this file,
--observe) waits for the robot to drive (faster than half of 1 m/s for a second: on eq 59's
hills the centre's speed varies about the command), takes the workstation's end of the link
down (`ip link set ... down`) for --cut seconds, brings it up again and measures:

* at rest: the first actuator state with every velocity exactly 0 after the cut. The watchdog
  zeroes the set-points command_timeout after the last command it accepted, checked once per
  period 1/rate, and the actuators then ramp to rest at max_acceleration (docs/hardware_interface.md,
  "Command-timeout watchdog"): at rest within command_timeout + 1/rate + |v|/max_acceleration
  of the last command, all three read from the hardware interface's parameters.
* the distance the robot travelled after the cut (the odometry's path length from the cut to
  the restore). diff_drive_controller's test of the same watchdog allows 0.8 m after a 1 m/s
  command with a 0.5 s timeout; for this robot (R = 0.2 m, 5 rad/s, 50 rad/s^2) the expectation
  is 1 m/s x (0.5 + 0.01) s + R (5 rad/s)^2 / (2 x 50 rad/s^2) = 0.56 m, and the 0.8 m bound
  leaves 0.24 s of scheduling latency on a busy machine. The same slack bounds the time to rest.
* after the restore: when commands reach the robot again, how many of them were sent during
  the cut (stamped before the restore), and whether the robot drives again.

Exit 0 with "SKIPPED: ..." where it cannot run (not root, no `ip`, namespaces not allowed, the
package not in the environment); 1 when a check fails. Namespaces and every process it started
are removed on every exit path (a finally block, SIGINT/SIGTERM/SIGHUP turned into an exit; the
processes are found by their namespace, `ip netns pids`, so roslaunch's nodes, each in a session
of its own, are found too). Namespaces left by a run that was killed outright (SIGKILL) are
removed by the next run. The processes' logs stay in a /tmp directory when a check fails.
What it found, and why: README, "Two hosts".
"""
import argparse
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from xml.sax.saxutils import escape

SOURCE = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
NS_PATTERN = re.compile(r'^sr2h(\d+)(robot|ws)$')
ROBOT_IP, WORKSTATION_IP = '10.210.0.1', '10.210.0.2'
LINK = 'link0'
STACK_NS = '/sphere'
SPEED = 1.0             # [m/s] the operator's command
DIFF_DRIVE_BOUND = 0.8  # [m] travelled after the cut (diff_drive_controller's test)
WATCHDOG_SLACK = 0.24   # [s] the same bound's latency at 1 m/s, for the time to rest
EXIT_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


class Skip(Exception):
    pass


class Exit(Exception):
    pass


def run(*command, check=True):
    return subprocess.run(command, capture_output=True, text=True, check=check, timeout=30)


def netns_pids(name):
    result = run('ip', 'netns', 'pids', name, check=False)
    return [int(p) for p in result.stdout.split()]


def remove_namespace(name):
    """Kills what still runs in namespace `name` (processes this script started there) and
    deletes it, with its end of the veth pair (the other end goes with it)."""
    for pid in netns_pids(name):
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    deadline = time.time() + 5
    while netns_pids(name) and time.time() < deadline:
        time.sleep(0.1)
    run('ip', 'netns', 'del', name, check=False)


def remove_stale_namespaces():
    """Namespaces of earlier runs whose script is gone (killed outright, no finally)."""
    for line in run('ip', 'netns', 'list', check=False).stdout.splitlines():
        match = NS_PATTERN.match(line.split()[0]) if line.strip() else None
        if match and not os.path.exists('/proc/%s' % match.group(1)):
            remove_namespace(line.split()[0])


class TwoHosts:
    """Two namespaces, the processes started in them, and their removal."""

    def __init__(self, logs, master):
        self.logs = logs
        self.robot = 'sr2h%drobot' % os.getpid()
        self.workstation = 'sr2h%dws' % os.getpid()
        self.master = (self.robot, ROBOT_IP) if master == 'robot' else (self.workstation,
                                                                        WORKSTATION_IP)
        self.master_uri = 'http://%s:11311' % self.master[1]
        self.namespaces = []
        self.processes = []

    def create(self):
        for name in (self.robot, self.workstation):
            result = run('ip', 'netns', 'add', name, check=False)
            if result.returncode != 0:
                raise Skip('network namespaces are not allowed here (ip netns add: %s)'
                           % result.stderr.strip())
            self.namespaces.append(name)
            run('ip', '-n', name, 'link', 'set', 'lo', 'up')
        veth = run('ip', 'link', 'add', LINK, 'netns', self.robot, 'type', 'veth',
                   'peer', 'name', LINK, 'netns', self.workstation, check=False)
        if veth.returncode != 0:
            raise Skip('no veth pair here (ip link add: %s)' % veth.stderr.strip())
        for name, address in ((self.robot, ROBOT_IP), (self.workstation, WORKSTATION_IP)):
            run('ip', '-n', name, 'addr', 'add', address + '/24', 'dev', LINK)
            run('ip', '-n', name, 'link', 'set', LINK, 'up')

    def environment(self, address):
        env = dict(os.environ, ROS_IP=address, ROS_MASTER_URI=self.master_uri,
                   ROS_HOME=os.path.join(self.logs, 'ros_home_' + address))
        env.pop('ROS_HOSTNAME', None)  # it would take precedence over ROS_IP
        return env

    def start(self, namespace, address, label, *command):
        """Runs command in the namespace, its output in label.log."""
        with open(os.path.join(self.logs, label + '.log'), 'w') as log:
            process = subprocess.Popen(('ip', 'netns', 'exec', namespace) + command,
                                       env=self.environment(address), stdout=log,
                                       stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                       start_new_session=True)
        self.processes.append(process)
        return process

    def wait_for_master(self, timeout):
        """Until the master answers on its host (a roslaunch started before would start a
        master of its own)."""
        namespace, address = self.master
        probe = ('ip', 'netns', 'exec', namespace, sys.executable, '-c',
                 'import rosgraph, sys; sys.exit(not rosgraph.is_master_online())')
        deadline = time.time() + timeout
        while subprocess.run(probe, env=self.environment(address)).returncode != 0:
            if time.time() > deadline:
                raise AssertionError('no master at %s after %.0f s' % (self.master_uri, timeout))
            time.sleep(0.2)

    def stop(self):
        """SIGINT to everything started (roslaunch shuts its nodes down), then whatever is still
        in the namespaces is killed and the namespaces deleted. A second signal must not cut
        this short."""
        for signum in EXIT_SIGNALS:
            signal.signal(signum, signal.SIG_IGN)
        for process in reversed(self.processes):
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
        deadline = time.time() + 10
        for process in self.processes:
            try:
                process.wait(timeout=max(0.1, deadline - time.time()))
            except subprocess.TimeoutExpired:
                pass
        for name in self.namespaces:
            remove_namespace(name)
        self.namespaces = []


def stack(part):
    return ('roslaunch', os.path.join(SOURCE, 'launch', 'terrain_stack.launch'), 'part:=' + part,
            'clock:=wall', 'mode:=teleop', 'duration:=0')


def raise_exit(signum, _frame):
    raise Exit('signal %d' % signum)


def check_figures(figures):
    """The checks of the module's docstring, as failure messages."""
    failures = []
    expected_rest = figures['command_timeout'] + figures['period'] + figures['ramp']
    if figures['rest_after_last_command'] is None:
        failures.append('the actuators never came to rest during the cut')
    elif figures['rest_after_last_command'] > expected_rest + WATCHDOG_SLACK:
        failures.append('at rest %.3f s after the last command, beyond %.3f + %.2f s'
                        % (figures['rest_after_last_command'], expected_rest, WATCHDOG_SLACK))
    if figures['distance_after_cut'] >= DIFF_DRIVE_BOUND:
        failures.append('travelled %.3f m after the cut, not less than %.1f m'
                        % (figures['distance_after_cut'], DIFF_DRIVE_BOUND))
    if figures['speed_at_rest'] > 1e-9:
        failures.append('moved during the cut after coming to rest (%.3g m/s)'
                        % figures['speed_at_rest'])
    if figures['moving_again_after_restore'] is None:
        failures.append('the robot did not drive again after the link came back')
    return failures


def write_junit(path, seconds, failures, skipped, text):
    body = ('<skipped message="%s"/>' % escape(skipped, {'"': '&quot;'}) if skipped else
            '<failure message="%s"/>' % escape('; '.join(failures), {'"': '&quot;'})
            if failures else '') + '<system-out>%s</system-out>' % escape(text)
    with open(path, 'w') as f:
        f.write('<?xml version="1.0" encoding="utf-8"?>\n<testsuite name="two_hosts" tests="1" '
                'failures="%d" errors="0" skipped="%d" time="%.1f"><testcase classname='
                '"two_hosts" name="cut_link" time="%.1f">%s</testcase></testsuite>\n'
                % (bool(failures), bool(skipped), seconds, seconds, body))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--cut', type=float, default=5.0, help='seconds the link stays down')
    parser.add_argument('--master', choices=('robot', 'workstation'), default='robot',
                        help='the host of the master (default: the robot)')
    parser.add_argument('--junit', help='write a JUnit result here (for catkin run_tests)')
    parser.add_argument('--observe', action='store_true', help=argparse.SUPPRESS)
    parser.add_argument('--workstation-ns', help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.observe:
        return observe(args.workstation_ns, args.cut)

    started = time.time()
    skipped, failures, text = None, [], ''
    try:
        failures, text = two_hosts(args.cut, args.master)
    except Skip as reason:
        skipped = str(reason)
        print('SKIPPED: %s' % skipped)
    except Exit as reason:
        failures = ['stopped by %s' % reason]
    seconds = time.time() - started
    print('wall time %.1f s' % seconds)
    if args.junit:
        write_junit(args.junit, seconds, failures, skipped, text)
    for failure in failures:
        print('FAILED: ' + failure)
    return 1 if failures else 0


def two_hosts(cut, master):
    if os.geteuid() != 0:
        raise Skip('needs root (network namespaces); run it with sudo')
    if not shutil.which('ip'):
        raise Skip('no `ip` (Debian: iproute2)')
    if not shutil.which('roslaunch') or run('rospack', 'find', 'spherical_robots',
                                              check=False).returncode != 0:
        raise Skip('spherical_robots is not in the environment: `. install/setup.sh` first')
    for signum in EXIT_SIGNALS:
        signal.signal(signum, raise_exit)
    remove_stale_namespaces()
    logs = tempfile.mkdtemp(prefix='two_hosts_cut_link.')
    hosts = TwoHosts(logs, master)
    failures = ['stopped before its measurements']
    try:
        hosts.create()
        failures, text = drive_and_cut(hosts, cut)
        return failures, text
    except Skip:
        failures = []
        raise
    finally:
        hosts.stop()
        if failures:
            print('logs: %s' % logs)
        else:
            shutil.rmtree(logs, ignore_errors=True)


def drive_and_cut(hosts, cut):
    """Starts the master, both halves, the operator and the observer: the checks' failures
    and the report."""
    try:
        hosts.start(*hosts.master, 'roscore', 'roscore', '-p', '11311')
        hosts.wait_for_master(60)
        hosts.start(hosts.robot, ROBOT_IP, 'robot', *stack('robot'))
        hosts.start(hosts.workstation, WORKSTATION_IP, 'workstation', *stack('workstation'))
        hosts.start(hosts.workstation, WORKSTATION_IP, 'operator', 'rostopic', 'pub', '-r', '20',
                    STACK_NS + '/cmd_vel', 'geometry_msgs/Twist',
                    '{linear: {x: %g}}' % SPEED)
        observer = hosts.start(hosts.robot, ROBOT_IP, 'observer', sys.executable,
                               os.path.realpath(__file__), '--observe', '--cut', str(cut),
                               '--workstation-ns', hosts.workstation)
        observer.wait(timeout=240)
    except subprocess.TimeoutExpired:
        return ['the observer did not finish within 240 s'], ''
    except AssertionError as failure:
        return [str(failure)], ''
    with open(os.path.join(hosts.logs, 'observer.log')) as log:
        lines = log.read().splitlines()
    result = [l for l in lines if l.startswith('{')]
    if observer.returncode != 0 or not result:
        return ['the observer failed (exit %s):\n  %s'
                % (observer.returncode, '\n  '.join(lines[-15:]))], ''
    figures = json.loads(result[-1])
    text = report(figures)
    print(text)
    return check_figures(figures), text


def report(f):
    """The figures, as the lines it prints and the JUnit result keeps."""
    return '\n'.join([
        'two hosts, link cut for %.1f s while driving at %.2f m/s (actuators at %.2f rad/s at most):'
        % (f['cut_seconds'], f['speed_before_cut'], f['rate_before_cut']),
        '  last command reached the robot %.3f s before the cut' % f['last_command_before_cut'],
        '  at rest %.3f s after the last command, %.3f s after the cut (expected %.3f s = '
        'command_timeout %.2f + period %.3f + ramp %.3f)'
        % (f['rest_after_last_command'] or math.nan, f['rest_after_cut'] or math.nan,
           f['command_timeout'] + f['period'] + f['ramp'], f['command_timeout'], f['period'],
           f['ramp']),
        '  travelled %.3f m after the cut (bound %.1f m)' % (f['distance_after_cut'],
                                                             DIFF_DRIVE_BOUND),
        '  after the restore: the first command arrived %.3f s later; %d commands sent during '
        'the cut arrived after it (the oldest %.2f s old); moving again %.3f s, over %.2f m/s '
        'again %.3f s after the restore'
        % (f['first_command_after_restore'] or math.nan, f['stale_commands'],
           f['oldest_stale_age'], f['moving_again_after_restore'] or math.nan,
           0.5 * SPEED, f['driving_again_after_restore'] or math.nan)])


# --- the observer, in the robot's namespace ---------------------------------------------------

def observe(workstation_ns, cut):
    import rospy
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import JointState

    rospy.init_node('two_hosts_observer', disable_signals=True)
    lock = threading.Lock()
    received = {'odom': [], 'state': [], 'command': []}

    def keep(key):
        def callback(msg):
            with lock:
                received[key].append((time.time(), msg))
        return callback

    rospy.Subscriber(STACK_NS + '/odom', Odometry, keep('odom'), queue_size=1000)
    rospy.Subscriber(STACK_NS + '/actuators/state', JointState, keep('state'), queue_size=1000)
    rospy.Subscriber(STACK_NS + '/actuators/command', JointState, keep('command'),
                     queue_size=1000)

    def since(key, t):
        with lock:
            return [(at, msg) for at, msg in received[key] if at >= t]

    def wait_for(condition, timeout):
        deadline = time.time() + timeout
        while not condition():
            if time.time() > deadline:
                return False
            time.sleep(0.05)
        return True

    # On eq 59's hills the centre's speed varies about the commanded one (0.84 m/s on the
    # first slope for 1 m/s): driving is over half of it for a whole second.
    def driving(t):
        odom = since('odom', t)
        return odom and all(m.twist.twist.linear.x > 0.5 * SPEED for _, m in odom)

    if not wait_for(lambda: len(since('odom', time.time() - 1.0)) > 20 and
                    driving(time.time() - 1.0), 120):
        recent = [round(m.twist.twist.linear.x, 3) for _, m in since('odom', time.time() - 1.0)]
        print('the robot did not drive (over half of %g m/s) within 120 s: %d odometry messages in the last '
              'second, forward speeds %s, %d commands in all'
              % (SPEED, len(recent), sorted(set(recent))[:10], len(received['command'])))
        return 1
    hardware = rospy.get_param(STACK_NS + '/hardware_interface')

    link = ['ip', '-n', workstation_ns, 'link', 'set', LINK]
    t_cut = time.time()
    subprocess.run(link + ['down'], check=True)
    time.sleep(cut)
    t_restore = time.time()
    subprocess.run(link + ['up'], check=True)
    # Recovered, or (the checks say which) not within a minute.
    wait_for(lambda: driving(time.time() - 1.0) and since('odom', t_restore + 1.0), 60)

    with lock:
        commands = list(received['command'])
        states = list(received['state'])
        odom = list(received['odom'])
    last_command = max(at for at, _ in commands if at < t_cut)
    # The actuators ramp to rest from their velocities at the cut.
    rate_at_cut = max(abs(v) for v in [m for at, m in states if at < t_cut][-1].velocity)
    rest = next((m.header.stamp.to_sec() for at, m in states
                 if t_cut <= at < t_restore and all(v == 0.0 for v in m.velocity)), None)
    during = [m for at, m in odom if t_cut <= m.header.stamp.to_sec() <= t_restore]
    before = [m for at, m in odom if m.header.stamp.to_sec() <= t_cut][-1:]
    positions = [m.pose.pose.position for m in before + during]
    after = [(at, m) for at, m in commands if at >= t_restore]
    stale = [m for _, m in after if m.header.stamp.to_sec() < t_restore]
    moving = next((m.header.stamp.to_sec() for at, m in states
                   if at >= t_restore and any(v != 0.0 for v in m.velocity)), None)
    driving_again = next((m.header.stamp.to_sec() for _, m in odom
                          if m.header.stamp.to_sec() >= t_restore and
                          m.twist.twist.linear.x > 0.5 * SPEED), None)
    figures = {
        'cut_seconds': cut, 'command_timeout': hardware['command_timeout'],
        'period': 1.0 / hardware['rate'], 'ramp': rate_at_cut / hardware['max_acceleration'],
        'rate_before_cut': rate_at_cut, 'speed_before_cut': before[0].twist.twist.linear.x,
        'last_command_before_cut': t_cut - last_command,
        'rest_after_last_command': rest and rest - last_command,
        'rest_after_cut': rest and rest - t_cut,
        'distance_after_cut': sum(math.dist((a.x, a.y, a.z), (b.x, b.y, b.z))
                                  for a, b in zip(positions, positions[1:])),
        'speed_at_rest': max((abs(m.twist.twist.linear.x) for m in during
                              if rest and m.header.stamp.to_sec() > rest + 0.05), default=0.0),
        'first_command_after_restore': after[0][0] - t_restore if after else None,
        'stale_commands': len(stale),
        'oldest_stale_age': (t_restore - min(m.header.stamp.to_sec() for m in stale)
                             if stale else 0.0),
        'moving_again_after_restore': moving and moving - t_restore,
        'driving_again_after_restore': driving_again and driving_again - t_restore,
    }
    print(json.dumps(figures), flush=True)
    rospy.signal_shutdown('done')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
