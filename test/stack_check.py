#!/usr/bin/env python3
"""rostest of the stacks (launch/terrain_stack.launch, launch/roller_stack.launch,
launch/norma_stack.launch), headless, in simulated time.

Runs in the stack's namespace (test/terrain_*.test, test/roller_*.test). Private params: ~mode
(tracking | teleop | seam | roller | norma | smoothness | user_path; see the classes) and
~frame_prefix. Times are simulated (the plant owns /clock), bounded by generous wall-clock
deadlines. In lock-step a run does not depend on the machine's load, so with ~batch the tracking
error must equal the batch run's (sphere_sim terrain --loop sampled) to 1e-9; the contact point
lies on the surface, which the plant never integrates off, to 1e-6.
"""
import functools
import math
import os
import subprocess
import time
import unittest

import rosnode
import rospy
import rostest
import tf2_ros
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from geometry_msgs.msg import PoseStamped, Twist, Vector3
from nav_msgs.msg import Odometry, Path
from sensor_msgs.msg import JointState
from std_msgs.msg import Bool
from visualization_msgs.msg import Marker

from spherical_robots.msg import NormaState, RollerDrive, TerrainState, TrackingError
import spherical_robots_testing as testing
from spherical_robots_testing import Recorder, first_at_rest, silenced

PKG = 'spherical_robots'
NAME = 'stack_check'
WALL_DEADLINE = 120.0          # [s] wall, for anything the stack should do in time
CMD_VEL_TIMEOUT = 0.5          # [s] wall: pure_pursuit_controller ~cmd_vel_timeout in teleop
SETTLE = (40.0, 60.0)          # [s] simulated window in which tracking has converged
SLACK = 0.5                    # [s] simulated: message latency at 10x real time (50 ms of wall)
PLANT_STATUS = 'terrain_plant: terrain plant'
CONTROLLER_STATUS = 'pure_pursuit_controller: pure pursuit controller'
NODES = ['terrain_plant', 'pure_pursuit_controller', 'hardware_interface',
         'robot_state_publisher']


# Every wait of this script is bounded by WALL_DEADLINE unless it says otherwise.
wait_until = functools.partial(testing.wait_until, timeout=WALL_DEADLINE)
sim_sleep = functools.partial(testing.sim_sleep, timeout=WALL_DEADLINE)
publish_until = functools.partial(testing.publish_until, timeout=WALL_DEADLINE)


def publish_when_connected(publisher, msg):
    wait_until(lambda: publisher.get_num_connections() > 0,
               'a subscriber on ' + publisher.resolved_name)
    publisher.publish(msg)


def tracking_in_window(errors, first_step=None):
    """Mean and max |e_t| over the simulated SETTLE window, from the stack's first step (its stamp
    [s], in lock-step one plant step) or, if not given, from the first tracking_error received."""
    wait_until(lambda: errors.count() > 0, 'the first tracking_error message')
    start = (int(round(first_step * 1e9)) if first_step is not None
             else errors.since(0)[0].header.stamp.to_nsec())
    wait_until(lambda: errors.last().header.stamp.to_nsec() - start > SETTLE[1] * 1e9,
               '%.0f s of simulated tracking' % SETTLE[1])
    window = [m.error_norm for m in errors.since(0)
              if SETTLE[0] * 1e9 <= m.header.stamp.to_nsec() - start <= SETTLE[1] * 1e9]
    if len(window) <= 200:
        raise AssertionError('too few tracking_error messages in the window: %d' % len(window))
    mean, worst = sum(window) / len(window), max(window)
    rospy.loginfo('|e_t| over simulated t in [%g, %g] s: mean %.4g m, max %.4g m, %d samples',
                  SETTLE[0], SETTLE[1], mean, worst, len(window))
    return mean, worst, len(window)


def batch_window(path_args=None):
    """The same figures from `sphere_sim terrain --loop sampled` on this stack's scenario: what a
    terrain stack in lock-step publishes, value for value (docs/lockstep.md,
    "Equal to the batch run"), so its bound is the batch run's figure itself. path_args: the
    batch run's path options (default: --path, the controller's built-in path)."""
    import csv
    import roslib.packages
    import rospkg
    plant, controller = rospy.get_param('terrain_plant'), rospy.get_param('pure_pursuit_controller')
    out = '/tmp/stack_check_batch_%d.csv' % os.getpid()
    # The roller stack loads config/roller.yaml (roller/...) into its namespace.
    stack = 'roller' if rospy.has_param('roller') else 'terrain'
    # A height map (terrain:= or config/terrain.yaml), relative to the package's directory.
    surface = rospy.get_param('terrain/surface')
    terrain = (['--terrain', os.path.join(rospkg.RosPack().get_path(PKG), surface['height_map'])]
               if surface['type'] == 'height_map' else [])
    subprocess.run([roslib.packages.find_node(PKG, 'sphere_sim')[0], 'terrain', '--loop', 'sampled',
                    '--stack', stack,
                    '--robot', controller['robot_type']] +
                   (path_args or ['--path', controller['path']]) +
                   ['--law', controller['law'], '--model', plant['contact_model'],
                    '--duration', '%g' % SETTLE[1], '--log-rate', '50',
                    '--config', rospkg.RosPack().get_path(PKG), '--out', out] + terrain +
                   (['--actuator-models', rospy.get_param('~actuator_models')]
                    if rospy.has_param('~actuator_models') else []),
                   check=True, stdout=subprocess.DEVNULL)
    with open(out) as f:
        window = [float(r['e_norm']) for r in csv.DictReader(f)
                  if SETTLE[0] * 1e9 <= round(float(r['t']) * 1e9) <= SETTLE[1] * 1e9]
    os.remove(out)
    return sum(window) / len(window), max(window), len(window)


def assert_tracking_like_the_batch_run(case, errors, path_args=None):
    """|e_t| over SETTLE equals the batch run's (batch_window) to 1e-9, mean and max."""
    mean, worst, count = tracking_in_window(errors, rospy.get_param('terrain_plant/step', 0.01))
    batch = batch_window(path_args)
    rospy.loginfo('batch run over the same window: mean %.17g m, max %.17g m, %d samples' % batch)
    case.assertEqual(count, batch[2])
    case.assertLessEqual(abs(mean - batch[0]), 1e-9)
    case.assertLessEqual(abs(worst - batch[1]), 1e-9)


def assert_tracking(case, errors):
    """~batch true (a terrain stack in lock-step, hardware:=sim or loopback; ~actuator_models the
    file the stack's actuator_models:= names, if any): |e_t| over SETTLE equals the batch run's to
    1e-9; otherwise below ~mean_bound and ~max_bound [m]."""
    if rospy.get_param('~batch', False):
        assert_tracking_like_the_batch_run(case, errors)
    else:
        mean, worst, _ = tracking_in_window(errors)
        case.assertLess(mean, float(rospy.get_param('~mean_bound')))
        case.assertLess(worst, float(rospy.get_param('~max_bound')))


class StackFixture(unittest.TestCase):
    """Subscriptions and helpers shared by both modes."""

    # Whether the check reads actuators/command (cls.commands): not every check, as Norma's are
    # 1 kHz.
    RECORDS_COMMANDS = False

    @classmethod
    def setUpClass(cls):
        cls.prefix = rospy.get_param('~frame_prefix', rospy.get_namespace().strip('/') + '/')
        cls.radius = 0.2  # urdf/terrain_robot.urdf and urdf/norma.urdf
        cls.odom = Recorder('odom', Odometry)
        cls.states = Recorder('terrain_state', TerrainState)
        cls.actuators = Recorder('actuators/state', JointState)
        cls.diagnostics = Recorder('/diagnostics', DiagnosticArray)
        # From the start, not from the test that reads it: a window of simulated time must not
        # have begun before the subscription (beside busy loops the tests before the terrain
        # stack's test_05 took longer than its 4 s of wall time to 40 s, and 643 of the window's
        # 1,001 messages came).
        cls.errors = Recorder('tracking_error', TrackingError)
        if cls.RECORDS_COMMANDS:
            cls.commands = Recorder('actuators/command', JointState)
        wait_until(lambda: cls.odom.count() > 0, 'the first odom message')

    def listen_to_tf(self):
        """A tf buffer fed from now until the end of the calling test: a listener for the whole run
        takes every transform (Norma: two sources at 1 kHz) in this Python process."""
        buffer = tf2_ros.Buffer()
        self.addCleanup(tf2_ros.TransformListener(buffer).unregister)
        return buffer

    def surface_height(self, x, y):
        """Paper eq 59 with config/terrain.yaml's a and w."""
        amplitude = float(rospy.get_param('terrain/surface/amplitude'))
        frequency = float(rospy.get_param('terrain/surface/frequency'))
        return amplitude * (math.cos(frequency * x) + math.cos(frequency * y) - 2.0)

    def diagnostic_value(self, status_suffix, key):
        """The latest value of `key` in the /diagnostics status whose name ends with the suffix."""
        for array in reversed(self.diagnostics.since(0)):
            for status in array.status:
                if status.name.endswith(status_suffix):
                    for pair in status.values:
                        if pair.key == key:
                            return pair.value
        return None

    def assert_nodes_alive(self, nodes=NODES):
        for node in nodes:
            name = rospy.resolve_name(node)
            self.assertTrue(rosnode.rosnode_ping(name, max_count=1), name + ' does not answer')

    def assert_still_publishing(self, recorders):
        counts = [recorder.count() for recorder in recorders]
        sim_sleep(2.0)
        # On a loaded machine this process's callbacks can trail its clock by a few tenths of a
        # second of wall time (seen: 4 of the 200 messages of 2 s at 10x), so the messages of those
        # 2 s get a further 10 s of wall time to arrive.
        for recorder, before in zip(recorders, counts):
            testing.wait_until(lambda: recorder.count() > before + 5,
                               recorder.subscriber.resolved_name + ' to go on publishing', 10.0)

    def rejected_count(self, status_suffix, topic):
        """How many messages on topic the node whose status ends with status_suffix rejected."""
        return int(self.diagnostic_value(status_suffix, rospy.resolve_name(topic) + ' rejected') or 0)

    def last_rejection(self, status_suffix, topic):
        """The reason the node gave for its last rejected message on topic ('' before one)."""
        return self.diagnostic_value(status_suffix, rospy.resolve_name(topic) + ' last rejection') \
            or ''

    def check_rejected_actuator_state(self):
        """A NaN and an incomplete actuators/state are ignored, counted, and kill nothing."""
        publisher = rospy.Publisher('actuators/state', JointState, queue_size=10)
        bad_nan = JointState(name=['theta', 'phi', 'psi'], velocity=[float('nan'), 0.0, 0.0])
        bad_missing = JointState(name=['theta'], velocity=[1.0])
        publish_until(publisher, [bad_nan, bad_missing],
                      lambda: self.rejected_count(PLANT_STATUS, 'actuators/state') >= 2,
                      'the plant to report 2 rejected actuators/state messages on /diagnostics')
        self.assert_still_publishing([self.odom, self.states, self.actuators])
        self.assert_nodes_alive()


class TrackingCheck(StackFixture):
    """mode:=tracking: the 3R robot follows the radius-2 circle on the eq 59 terrain."""

    def test_01_odometry(self):
        """REP 105: pose of base_link in odom, gravity-aligned; twist in base_link, so that the
        twist turned into odom, averaged over two messages, is the motion between them;
        covariances not 0."""
        # Past the start, whose actuator ramps change the velocity within a publish period.
        wait_until(lambda: self.odom.count() >= 300, '300 odom messages (6 s)')
        odom = self.odom.last()
        self.assertEqual(odom.header.frame_id, self.prefix + 'odom')
        self.assertEqual(odom.child_frame_id, self.prefix + 'base_link')
        p = odom.pose.pose.position
        self.assertTrue(all(math.isfinite(v) for v in (p.x, p.y, p.z)))
        for diagonal in (odom.pose.covariance[::7], odom.twist.covariance[::7]):
            self.assertTrue(all(v > 0.0 for v in diagonal), diagonal)
        def velocity_in_odom(msg):
            q, v = msg.pose.pose.orientation, msg.twist.twist.linear
            self.assertAlmostEqual(q.x, 0.0, delta=1e-12)  # z up: a turn about z only
            self.assertAlmostEqual(q.y, 0.0, delta=1e-12)
            yaw = 2.0 * math.atan2(q.z, q.w)
            return (math.cos(yaw) * v.x - math.sin(yaw) * v.y,
                    math.sin(yaw) * v.x + math.cos(yaw) * v.y, v.z)

        recent = self.odom.since(-20)
        for before, after in zip(recent, recent[1:]):
            dt = (after.header.stamp - before.header.stamp).to_sec()
            a, b = after.pose.pose.position, before.pose.pose.position
            moved = ((a.x - b.x) / dt, (a.y - b.y) / dt, (a.z - b.z) / dt)
            mean = [(u + w) / 2.0 for u, w in zip(velocity_in_odom(before), velocity_in_odom(after))]
            for axis in range(3):  # the trapezoid's error over 0.02 s while tracking: < 1 mm/s
                self.assertAlmostEqual(mean[axis], moved[axis], delta=1e-3)

    def test_02_tf(self):
        tf = self.listen_to_tf()
        # map -> odom (static) -> base_link -> shell (-> marker_link: robot_state_publisher), heading
        for child in ('odom', 'base_link', 'shell', 'heading', 'marker_link'):
            transform = tf.lookup_transform('map', self.prefix + child, rospy.Time(0),
                                            rospy.Duration(10.0))
            t = transform.transform.translation
            self.assertTrue(all(math.isfinite(v) for v in (t.x, t.y, t.z)), child)
        # The shell's centre is base_link's; the heading frame sits at the contact point, base_link
        # R above it along the normal.
        shell = tf.lookup_transform(self.prefix + 'base_link', self.prefix + 'shell',
                                    rospy.Time(0)).transform.translation
        self.assertEqual((shell.x, shell.y, shell.z), (0.0, 0.0, 0.0))
        base = tf.lookup_transform('map', self.prefix + 'base_link', rospy.Time(0))
        heading = tf.lookup_transform('map', self.prefix + 'heading', rospy.Time(0))
        b, h = base.transform.translation, heading.transform.translation
        # Transforms are published together but may be looked up at different times: allow the
        # distance travelled in a few steps.
        self.assertAlmostEqual(math.dist((b.x, b.y, b.z), (h.x, h.y, h.z)), self.radius, delta=0.05)

    def test_03_desired_path_latched(self):
        path = rospy.wait_for_message('desired_path', Path, timeout=30.0)
        self.assertEqual(path.header.frame_id, self.prefix + 'odom')
        self.assertGreaterEqual(len(path.poses), 100)
        for pose in path.poses:
            q = pose.pose.position
            self.assertAlmostEqual(math.hypot(q.x, q.y), 2.0, delta=1e-6)
            self.assertAlmostEqual(q.z, self.surface_height(q.x, q.y), delta=1e-6)
        first, last = path.poses[0].pose.position, path.poses[-1].pose.position
        self.assertAlmostEqual(math.dist((first.x, first.y), (last.x, last.y)), 0.0, delta=1e-6)
        angles = [math.atan2(p.pose.position.y, p.pose.position.x) % (2 * math.pi) for p in path.poses]
        self.assertGreater(max(angles) - min(angles), 1.9 * math.pi)  # one whole period

    def test_04_contact_point_on_surface(self):
        wait_until(lambda: self.states.count() >= 50, '50 terrain_state messages')
        for msg in self.states.since(0)[-50:]:
            c, o, n = msg.contact_point, msg.centre, msg.normal
            self.assertAlmostEqual(c.z, self.surface_height(c.x, c.y), delta=1e-6)
            self.assertAlmostEqual(math.sqrt(n.x ** 2 + n.y ** 2 + n.z ** 2), 1.0, delta=1e-9)
            for axis in ('x', 'y', 'z'):
                self.assertAlmostEqual(getattr(o, axis), getattr(c, axis) + self.radius * getattr(n, axis),
                                       delta=1e-9)

    def test_05_tracking_converges(self):
        assert_tracking(self, self.errors)

    def test_06_bad_messages_kill_nothing(self):
        self.check_rejected_actuator_state()
        # The controller ignores odometry it cannot use, and so does the hardware interface with a
        # non-finite set-point.
        odom_pub = rospy.Publisher('odom', Odometry, queue_size=10)
        bad_odom = self.odom.last()
        bad_odom.pose.pose.position.x = float('nan')
        publish_until(odom_pub, [bad_odom],
                      lambda: self.rejected_count(CONTROLLER_STATUS, 'odom') >= 1,
                      'the controller to report a rejected odom on /diagnostics')
        command_pub = rospy.Publisher('actuators/command', JointState, queue_size=10)
        publish_when_connected(command_pub, JointState(name=['theta', 'phi', 'psi'],
                                                       velocity=[float('nan'), 0.0, 0.0]))
        self.assert_still_publishing([self.odom, self.errors, self.actuators])
        self.assert_nodes_alive()
        recent = [m.error_norm for m in self.errors.since(-50)]
        self.assertLess(max(recent), 0.2, 'tracking degraded after the bad messages')


class TeleopCheck(StackFixture):
    """mode:=teleop: cmd_vel drives the 3R robot; stale or bad cmd_vel stops or is ignored."""

    RECORDS_COMMANDS = True

    def drive(self, twist, seconds):
        """Publishes twist at 10 Hz of wall time, as a joystick does, for `seconds` of simulated
        time: at 10x that is 1 s of simulated time apart, twice the 0.5 s cmd_vel timeout, which
        counts wall time (a person's commands) and so keeps the robot moving."""
        publisher = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        publish_when_connected(publisher, twist)
        start = rospy.Time.now().to_sec()
        end = start + seconds
        deadline = time.time() + WALL_DEADLINE
        sent = []  # (wall time, simulated time) of each command
        while rospy.Time.now().to_sec() < end and time.time() < deadline:
            publisher.publish(twist)
            sent.append((time.time(), rospy.Time.now().to_sec()))
            time.sleep(0.1)
        # Commanded means a command less than the timeout old: where this process itself was
        # descheduled for longer than that between two commands, the stack rightly stopped.
        lapses = [(a[1], b[1]) for a, b in zip(sent, sent[1:]) if b[0] - a[0] > CMD_VEL_TIMEOUT]
        # So is a controller that sent no command for longer than the hardware interface's
        # command_timeout [s] of simulated time: with clock:=free at 10x that is 50 ms of wall
        # time without the CPU (seen: 31 of 125 states at rest beside a build), and the hardware
        # interface rightly stops the actuators. In lock-step there is no such gap.
        timeout = float(rospy.get_param('hardware_interface/command_timeout'))
        stamps = [m.header.stamp.to_sec() for m in self.commands.since(0)]
        stalls = [(a, b) for a, b in zip(stamps, stamps[1:]) if start <= b and a <= end
                  and b - a > timeout]
        for what, gaps in (('this checker sent no cmd_vel for longer than %g s of wall time'
                            % CMD_VEL_TIMEOUT, lapses),
                           ('the controller sent no command for longer than %g s of simulated '
                            'time' % timeout, stalls)):
            if gaps:
                rospy.logwarn('teleop: %s %d times; those stretches are left out', what, len(gaps))
        self.assert_moved_at_every_state(start + 0.5, end, lapses + stalls)

    def assert_moved_at_every_state(self, start, end, lapses=()):
        """While commanded (after the actuators' ramp), every terrain_state is on from the last:
        no bursts of motion between stretches at rest (issue 19: at 10x with a command timeout
        in simulated time, 1,941 of 4,065 samples were at rest). lapses: (from, to) simulated
        times without a live command (drive()), left out with the actuators' ramp after them."""
        def commanded(t):
            return not any(a <= t <= b + 0.5 for a, b in lapses)
        states = [m for m in self.states.since(0)
                  if start <= m.header.stamp.to_sec() <= end and commanded(m.header.stamp.to_sec())]
        self.assertGreater(len(states), 10, 'too few terrain_state messages while driving')
        at_rest = sum(1 for a, b in zip(states, states[1:])
                      if math.dist((a.contact_point.x, a.contact_point.y),
                                   (b.contact_point.x, b.contact_point.y)) < 1e-6)
        rospy.loginfo('teleop: %d of %d terrain_state steps at rest while commanded',
                      at_rest, len(states) - 1)
        self.assertEqual(at_rest, 0, 'the robot stopped while commanded')

    def contact_point(self):
        c = self.states.last().contact_point
        return c.x, c.y

    def test_01_drive_and_stop(self):
        wait_until(lambda: self.states.count() > 0, 'the first terrain_state message')
        # The robot starts on the peak at the origin, heading along +x (psi = 0).
        x0, y0 = self.contact_point()
        self.drive(Twist(linear=Vector3(x=0.2)), 4.0)
        x1, y1 = self.contact_point()
        # 0.2 m/s for 4 s, less the actuators' ramp: about 0.8 m forward, along +x by symmetry.
        self.assertGreater(x1 - x0, 0.5, 'linear.x did not drive forward')
        self.assertLess(abs(y1 - y0), 0.05)
        # linear.y > 0 moves left: lateral rate -v_y / R, centre velocity -R phi_dot l.
        self.drive(Twist(linear=Vector3(y=0.2)), 3.0)
        x2, y2 = self.contact_point()
        self.assertGreater(y2 - y1, 0.3, 'linear.y did not drive left')
        # cmd_vel goes stale after 0.5 s of wall time: set-points become zero and the robot
        # stops (the actuators ramp down at 50 rad/s^2 within 0.4 s of simulated time).
        time.sleep(1.0)
        sim_sleep(0.5)
        x3, y3 = self.contact_point()
        sim_sleep(2.0)
        x4, y4 = self.contact_point()
        rospy.loginfo('teleop: forward %.3f m (y drift %.4f m), left %.3f m, drift when stale %.2e m',
                      x1 - x0, y1 - y0, y2 - y1, math.dist((x3, y3), (x4, y4)))
        self.assertLess(math.dist((x3, y3), (x4, y4)), 1e-3, 'still moving with a stale cmd_vel')

    def test_02_bad_cmd_vel_kills_nothing(self):
        publisher = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        publish_until(publisher, [Twist(linear=Vector3(x=float('nan')))],
                      lambda: self.rejected_count(CONTROLLER_STATUS, 'cmd_vel') >= 1,
                      'the controller to report a rejected cmd_vel on /diagnostics')
        self.assert_nodes_alive()
        self.check_rejected_actuator_state()

    def test_03_implausible_cmd_vel_moves_nothing(self):
        """1e300 m/s is finite but no person's command: rejected, not clamped (it drove the robot
        about 40 m at its limits). The robot is at rest (stale cmd_vel) and stays there."""
        wait_until(lambda: self.states.count() > 0, 'the first terrain_state message')
        sim_sleep(1.0)
        x0, y0 = self.contact_point()
        publisher = rospy.Publisher('cmd_vel', Twist, queue_size=100)
        publish_until(publisher, [Twist(linear=Vector3(x=1e300)), Twist(angular=Vector3(z=-1e300)),
                                  Twist(linear=Vector3(y=11.0))],
                      lambda: 'magnitude <= 10' in self.last_rejection(CONTROLLER_STATUS, 'cmd_vel'),
                      'the controller to reject the implausible cmd_vel')
        sim_sleep(2.0)
        x1, y1 = self.contact_point()
        self.assertLess(math.dist((x0, y0), (x1, y1)), 1e-3,
                        'an implausible cmd_vel moved the robot %.3f m' % math.dist((x0, y0), (x1, y1)))


class SeamCheck(StackFixture):
    """mode:=seam: the hardware-interface seam inside a running stack (docs/hardware_interface.md),
    whichever implementation of the contract the stack started (hardware:=sim | loopback). Private
    params: ~mean_bound, ~max_bound [m] for |e_t| over the SETTLE window; ~safety (bool) also
    engages the e-stop mid-run and then silences the controller to fire the watchdog, which needs
    ideal measurements (exact zeros: no noise model)."""

    RECORDS_COMMANDS = True

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.e_stop_pub = rospy.Publisher('estop', Bool, queue_size=1, latch=True)
        hardware = rospy.resolve_name('hardware_interface')
        cls.status_suffix = hardware.lstrip('/') + ': actuators'
        cls.timeout = float(rospy.get_param(hardware + '/command_timeout'))
        cls.max_acceleration = float(rospy.get_param(hardware + '/max_acceleration'))
        cls.period = 1.0 / float(rospy.get_param(hardware + '/rate'))

    def status_level(self):
        for array in reversed(self.diagnostics.since(0)):
            for status in array.status:
                if status.name == self.status_suffix:
                    return status.level, status.message
        return None, None

    def test_01_tracks_within_bounds(self):
        assert_tracking(self, self.errors)

    def test_02_e_stop_mid_run(self):
        if not rospy.get_param('~safety', False):
            self.skipTest('~safety is false (actuator models with noise: no exact zeros)')
        self.assertTrue(any(v != 0.0 for v in self.actuators.last().velocity), 'not moving')
        engaged = rospy.Time.now().to_sec()
        self.e_stop_pub.publish(Bool(data=True))
        # Stopped at once (not ramped): the first state at rest is the one sent on the e-stop, a
        # few ms of wall time later, i.e. within SLACK of simulated time at 10x.
        wait_until(lambda: first_at_rest(self.actuators, engaged) is not None, 'the e-stop')
        stopped = first_at_rest(self.actuators, engaged).header.stamp.to_sec()
        rospy.loginfo('e-stop: at rest %.3f s (simulated) after it was published',
                      stopped - engaged)
        self.assertLess(stopped - engaged, self.period + SLACK)
        wait_until(lambda: self.status_level()[0] == DiagnosticStatus.ERROR,
                   'an ERROR on /diagnostics for the e-stop')
        # Held while engaged, though the controller keeps commanding.
        sim_sleep(1.0)
        self.assertTrue(all(v == 0.0 for v in self.actuators.last().velocity))
        self.e_stop_pub.publish(Bool(data=False))
        wait_until(lambda: any(v != 0.0 for v in self.actuators.last().velocity),
                   'the controller to drive again after the release')

    def test_03_watchdog_when_controller_goes_silent(self):
        """The controller stopped mid-run (SIGSTOP: silent, neither dead, which would end the stack
        or restart the node, nor answering): the plant drops it after its lock-step timeout, and
        the hardware's watchdog brings every actuator to rest within timeout + |v|/a + one period
        of the last command, with a WARN on /diagnostics. Continued, it rejoins and drives again."""
        if not rospy.get_param('~safety', False):
            self.skipTest('~safety is false (actuator models with noise: no exact zeros)')
        sim_sleep(2.0)
        speed = max(abs(v) for v in self.actuators.last().velocity)
        self.assertGreater(speed, 0.0, 'not moving before the controller is stopped')
        with silenced(rospy.resolve_name('pure_pursuit_controller')):
            last_command = self.commands.timed_since(0)[-1][0]
            bound = self.timeout + speed / self.max_acceleration + self.period
            wait_until(lambda: first_at_rest(self.actuators, last_command) is not None,
                       'the watchdog to bring every actuator to rest')
            at_rest = first_at_rest(self.actuators, last_command).header.stamp.to_sec()
            rospy.loginfo('watchdog: at rest %.3f s (simulated) after the last command; bound '
                          'timeout + |v|/a + one period = %.3f s', at_rest - last_command, bound)
            self.assertLess(at_rest - last_command, bound + SLACK)
            self.assertGreater(at_rest - last_command, self.timeout - SLACK,
                               'watchdog fired early')
            wait_until(lambda: self.status_level()[0] == DiagnosticStatus.WARN and
                       'command timeout' in self.status_level()[1],
                       'a command-timeout WARN on /diagnostics')
        wait_until(lambda: self.commands.timed_since(0)[-1][0] > at_rest,
                   'the controller to rejoin and command again')


class RollerCheck(SeamCheck):
    """mode:=roller: the roller stack's seam checks, plus the friction drive's slip as published
    on roller_drive against eq 28 in closed form, S1 = -S2 = (v1 sin a1 - v2 sin a2) / 2, with the
    measured roller speeds and the configured arrangement angles."""

    def test_00_slip_is_eq_28(self):
        drives = Recorder('roller_drive', RollerDrive)
        # 10 s of simulated time at 100 Hz: the catch-up from the origin, where the rollers turn
        # hardest, starts whenever the controller's first command arrives.
        wait_until(lambda: drives.count() >= 1000, '1000 roller_drive messages')
        alpha1 = math.radians(float(rospy.get_param('roller/alpha1_deg')))
        alpha2 = math.radians(float(rospy.get_param('roller/alpha2_deg')))
        largest = 0.0
        for msg in drives.since(0):
            v1, v2 = msg.roller_speed
            expected = 0.5 * (v1 * math.sin(alpha1) - v2 * math.sin(alpha2))
            self.assertAlmostEqual(msg.slip[0], expected, delta=1e-9 * (1.0 + abs(expected)))
            self.assertAlmostEqual(msg.slip[1], -expected, delta=1e-9 * (1.0 + abs(expected)))
            largest = max(largest, abs(msg.slip[0]))
        rospy.loginfo('slip: |S1| up to %.4f m/s over %d samples', largest, drives.count())
        self.assertGreater(largest, 0.01, 'no slip at all with alpha1 = -alpha2 != 0')


class NormaCheck(StackFixture):
    """mode:=norma: Norma's stack with the paper's controller (eqs 48-51, Table 1) on eq 52, over
    the first ~norma_window simulated seconds. With ~batch (lock-step, ideal actuators) every
    state equals the sampled batch run's to 1e-9; otherwise, bounds from the continuous batch run
    of the same closed loop (docs/results.md): the stack must stay within ~error_bound of the path
    and end within ~batch_tolerance of the batch's position at the window's end (~batch_x,
    ~batch_y)."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.norma_states = Recorder('norma_state', NormaState)
        cls.joint_states = Recorder('joint_states', JointState)
        cls.window = float(rospy.get_param('~norma_window', 30.0))

    def test_01_tracks_like_the_batch_run(self):
        wait_until(lambda: self.norma_states.count() > 0 and
                   self.norma_states.last().header.stamp.to_sec() >= self.window,
                   '%.0f s of simulated time' % self.window, timeout=3 * WALL_DEADLINE)
        if rospy.get_param('~batch', False):
            self.equals_the_sampled_batch_run()
        else:
            end = next(m for m in self.norma_states.since(0)
                       if m.header.stamp.to_sec() >= self.window)
            worst = max(m.error_norm for m in self.errors.since(0)
                        if m.header.stamp.to_sec() <= self.window)
            batch = (float(rospy.get_param('~batch_x')), float(rospy.get_param('~batch_y')))
            offset = math.dist((end.x, end.y), batch)
            rospy.loginfo('norma: at t = %.3f s centre (%.4f, %.4f) m, batch (%.4f, %.4f): %.2e m '
                          'apart; max |e| %.4f m', end.header.stamp.to_sec(), end.x, end.y,
                          batch[0], batch[1], offset, worst)
            self.assertLess(worst, float(rospy.get_param('~error_bound')))
            self.assertLess(offset, float(rospy.get_param('~batch_tolerance')))
        for m in self.norma_states.since(0):
            self.assertTrue(all(math.isfinite(v) for v in list(m.q) + list(m.qd) + [m.energy]))
            self.assertLessEqual(abs(0.1 + m.q[3]), 0.2, 'the slider left the shaft')

    def equals_the_sampled_batch_run(self):
        """~batch: every norma_state this check received over the window equals the row of
        `sphere_sim norma --loop sampled` (the stack's loop without ROS) at the same time since
        the first step, to 1e-9 (docs/lockstep.md), and the stack's |e| stays within the batch
        run's largest."""
        import csv
        import roslib.packages
        first_step = int(round(float(rospy.get_param('norma_plant/step', 0.001)) * 1e9))
        out = '/tmp/stack_check_norma_%d.csv' % os.getpid()
        subprocess.run([roslib.packages.find_node(PKG, 'sphere_sim')[0], 'norma', '--loop', 'sampled',
                        '--controller', rospy.get_param('norma_controller/controller'),
                        '--variant', rospy.get_param('norma_plant/variant', 'text'),
                        '--duration', '%g' % self.window, '--log-rate', '1000', '--out', out],
                       check=True, stdout=subprocess.DEVNULL)
        with open(out) as f:
            rows = {int(round(float(r['t']) * 1e9)): r for r in csv.DictReader(f)}
        os.remove(out)
        columns = ['theta', 'alpha', 'phi', 'delta']
        compared, largest = 0, 0.0
        for m in self.norma_states.since(0):
            row = rows.get(m.header.stamp.to_nsec() - first_step)
            if row is None:
                continue
            values = ([(m.x, 'X'), (m.y, 'Y'), (m.psi, 'psi')] +
                      [(m.q[i], c) for i, c in enumerate(columns)] +
                      [(m.qd[i], c + 'd') for i, c in enumerate(columns)])
            largest = max([largest] + [abs(v - float(row[c])) for v, c in values])
            compared += 1
        worst = max(m.error_norm for m in self.errors.since(0)
                    if m.header.stamp.to_nsec() - first_step <= self.window * 1e9)
        batch_worst = max(float(r['err']) for r in rows.values())
        rospy.loginfo('norma: %d of %d states of the first %g s compared with the batch run: largest '
                      'difference %.3g; max |e| %.6f m (batch %.6f m)', compared, len(rows),
                      self.window, largest, worst, batch_worst)
        self.assertGreater(compared, 0.9 * len(rows), 'too few states received to compare')
        self.assertLessEqual(largest, 1e-9)
        self.assertLessEqual(worst, batch_worst + 1e-9)

    def test_02_joint_states_and_tf(self):
        tf = self.listen_to_tf()
        wait_until(lambda: self.joint_states.count() > 0, 'joint_states')
        msg = self.joint_states.last()
        self.assertEqual(list(msg.name),
                         ['tilt_joint', 'shell_joint', 'pendulum_joint', 'slider_joint'])
        state = self.norma_states.last()
        # phi, theta, alpha, delta (urdf/norma.urdf), at most one 20 ms publishing period apart
        # from the last state.
        for joint, coordinate in zip((0, 1, 2, 3), (2, 0, 1, 3)):
            self.assertAlmostEqual(msg.position[joint], state.q[coordinate], delta=0.05)
        for child in ('odom', 'base_link', 'tilt_link', 'shell_link', 'pendulum_link', 'slider_link'):
            transform = tf.lookup_transform('map', self.prefix + child, rospy.Time(0),
                                            rospy.Duration(10.0))
            t = transform.transform.translation
            self.assertTrue(all(math.isfinite(v) for v in (t.x, t.y, t.z)), child)
        base = tf.lookup_transform(self.prefix + 'odom', self.prefix + 'base_link', rospy.Time(0))
        self.assertAlmostEqual(base.transform.translation.z, self.radius, delta=1e-9)
        # REP 105: odom's pose in <prefix>odom, gravity-aligned, its twist in base_link: eqs 6
        # and 12 turned into {F_l}, forward R theta' cos(phi), leftward -R phi', of the state
        # with the same stamp. The latest odom whose state this check holds: at 1 kHz and
        # uncapped, rospy's queue of this busy check drops a message now and then (one run
        # lacked the state of the odom five from the end).
        wait_until(lambda: self.odom.count() > 10, '10 odom messages')
        states = {m.header.stamp: m for m in self.norma_states.since(0)}
        odom, same = next(((o, states[o.header.stamp]) for o in reversed(self.odom.since(0))
                           if o.header.stamp in states), (None, None))
        self.assertIsNotNone(odom, 'no odom with a norma_state of the same stamp among %d and %d'
                             % (self.odom.count(), len(states)))
        self.assertEqual(odom.header.frame_id, self.prefix + 'odom')
        self.assertEqual(odom.child_frame_id, self.prefix + 'base_link')
        q = odom.pose.pose.orientation
        self.assertEqual((q.x, q.y), (0.0, 0.0))
        self.assertTrue(all(v > 0.0 for v in odom.pose.covariance[::7]))
        self.assertAlmostEqual(odom.twist.twist.linear.x,
                               self.radius * same.qd[0] * math.cos(same.q[2]), delta=1e-12)
        self.assertAlmostEqual(odom.twist.twist.linear.y, -self.radius * same.qd[2], delta=1e-12)

    def test_03_bad_efforts_kill_nothing(self):
        publisher = rospy.Publisher('actuators/state', JointState, queue_size=10)
        bad = JointState(name=['pendulum_motor', 'slider_motor'], effort=[float('nan'), 0.0])
        publish_until(publisher, [bad],
                      lambda: self.rejected_count('norma_plant: norma plant',
                                                  'actuators/state') >= 1,
                      'the plant to report a rejected actuators/state on /diagnostics')
        self.assert_still_publishing([self.odom, self.norma_states])
        self.assert_nodes_alive(['norma_plant', 'norma_controller',
                                 'hardware_interface', 'robot_state_publisher'])
        self.assertTrue(all(math.isfinite(v) for v in self.norma_states.last().q))


    def test_04_gains_reconfigured_mid_run(self):
        """dynamic_reconfigure mid-run (cfg/NormaController.cfg): PID2's gains set to 0 make every
        later torque command exactly 0 (T = kp e + ki integral - kd beta_dot, nothing else), the
        loaded gains back make it non-zero again; a non-finite gain is refused and the last good
        gains are handed back."""
        from dynamic_reconfigure.client import Client
        client = Client('norma_controller', timeout=30.0)
        commands = Recorder('actuators/command', JointState)
        loaded = client.get_configuration(timeout=10.0)
        pid2 = {k: loaded[k] for k in ('pendulum_kp', 'pendulum_ki', 'pendulum_kd')}
        self.assertEqual(pid2, {'pendulum_kp': float(rospy.get_param('norma_controller/gains/pendulum/kp')),
                                'pendulum_ki': float(rospy.get_param('norma_controller/gains/pendulum/ki')),
                                'pendulum_kd': float(rospy.get_param('norma_controller/gains/pendulum/kd'))},
                         'the server must start from the gains the node loaded')

        def torques_after(stamp, span):
            """(stamp [s], torque) of every command stamped after `stamp`, up to `stamp` + span."""
            wait_until(lambda: commands.count() and
                       commands.last().header.stamp.to_sec() >= stamp + span,
                       'commands up to %.1f s' % (stamp + span))
            return [(m.header.stamp.to_sec(), dict(zip(m.name, m.effort))['pendulum_motor'])
                    for m in commands.since(0) if stamp < m.header.stamp.to_sec() <= stamp + span]

        def latest_stamp():
            return commands.last().header.stamp.to_sec() if commands.count() else 0.0

        # The step a change took effect at is found in the data, after the last command this node
        # had seen before asking: this node's own clock lags the loop's (by up to a /clock period,
        # more when the machine is busy), so a margin on it is not a bound.
        wait_until(lambda: commands.count() > 0, 'a recorded command')
        try:
            asked = latest_stamp()
            client.update_configuration({k: 0.0 for k in pid2})
            after = torques_after(asked, 8.0)
            first_zero = next((i for i, (_, torque) in enumerate(after)
                               if all(t == 0.0 for _, t in after[i:])), None)
            self.assertIsNotNone(first_zero, 'torques commanded with PID2 at zero: %s' % after[-5:])
            self.assertGreater(after[-1][0] - after[first_zero][0], 1.0,
                               'PID2 at zero took effect %.3f s after it was asked, too late to '
                               'show 1 s of zero torques' % (after[first_zero][0] - asked))

            kept = client.update_configuration({'pendulum_kp': float('nan')})
            self.assertEqual(kept['pendulum_kp'], 0.0, 'a NaN gain must be refused, 0 kept')
            wait_until(lambda: 'PID2 kp' in (self.diagnostic_value(
                           'norma_controller: norma controller', 'last refused reconfiguration')
                           or ''),
                       'diagnostics to name the refused gain')
        finally:
            asked = latest_stamp()
            client.update_configuration(pid2)
        self.assertTrue(any(t != 0.0 for _, t in torques_after(asked, 8.0)),
                        'torques with the loaded PID2 gains back')


def path_message(points, stamps=None, frame='map'):
    """A nav_msgs/Path through (x, y) points, its poses stamped `stamps` [s] (default all 0)."""
    msg = Path()
    msg.header.frame_id = frame
    for i, (x, y) in enumerate(points):
        pose = PoseStamped()
        pose.header.frame_id = frame
        pose.header.stamp = rospy.Time.from_sec(stamps[i] if stamps else 0.0)
        pose.pose.position.x, pose.pose.position.y = x, y
        pose.pose.orientation.w = 1.0
        msg.poses.append(pose)
    return msg


class UserPathCheck(StackFixture):
    """mode:=user_path: the terrain stack with path:=topic follows the untimed path of ~path_file
    that scripts/publish_path.py sent it, refuses bad paths keeping it, and takes a path in
    another frame through tf (test/terrain_user_path.test)."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.desired_paths = Recorder('desired_path', Path)
        cls.path_pub = rospy.Publisher('path', Path, queue_size=10)
        cls.path_file = rospy.get_param('~path_file')
        cls.speed = float(rospy.get_param('pure_pursuit_controller/untimed_speed'))

    def path_points(self):
        """The (x, y) rows of ~path_file (header and comments skipped)."""
        points = []
        with open(self.path_file) as f:
            for line in f:
                cells = line.strip().split(',')
                try:
                    points.append((float(cells[0]), float(cells[1])))
                except ValueError:
                    continue
        return points

    def controller_level(self):
        for array in reversed(self.diagnostics.since(0)):
            for status in array.status:
                if status.name.endswith(CONTROLLER_STATUS):
                    return status.level, status.message
        return None, ''

    def test_01_tracks_the_path_within_the_built_in_paths_bounds(self):
        assert_tracking_like_the_batch_run(
            self, self.errors, ['--path-file', self.path_file, '--speed', repr(self.speed)])
        points = self.path_points()
        end = sum(math.dist(a, b) for a, b in zip(points, points[1:])) / self.speed
        start = int(round(rospy.get_param('terrain_plant/step', 0.01) * 1e9))
        wait_until(lambda: self.errors.last().header.stamp.to_nsec() - start > (end + 5.0) * 1e9,
                   'the end of the path, %.0f s of simulated tracking' % (end + 5.0))
        run = [(m.header.stamp.to_nsec() - start, m.error_norm) for m in self.errors.since(0)]
        after = [e for t, e in run if t >= SETTLE[0] * 1e9]
        worst, mean = max(e for _, e in run), sum(after) / len(after)
        rospy.loginfo('user path (%.1f s at %g m/s): max |e_t| %.4g m over the run, mean %.4g m '
                      'after %g s', end, self.speed, worst, mean, SETTLE[0])
        # test_terrain_tracking's bounds for the circle: from the start, as the path starts where
        # the robot stands.
        self.assertLess(worst, 0.3)
        self.assertLess(mean, 0.1)

    def test_02_bad_paths_are_refused_and_the_path_kept(self):
        wait_until(lambda: self.diagnostic_value(CONTROLLER_STATUS, 'path') is not None,
                   'the controller\'s path on /diagnostics')
        followed = self.diagnostic_value(CONTROLLER_STATUS, 'path')
        self.assertIn('sampled path of %d points' % len(self.path_points()), followed)
        desired_paths = self.desired_paths.count()
        topic = rospy.resolve_name('path')
        line = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]
        cases = [
            ('NaN', path_message([(0.0, 0.0), (1.0, 0.0), (2.0, float('nan'))]),
             ['poses[2].pose.position.y', 'nan']),
            ('one pose', path_message([(0.0, 0.0)]), ['at least 2 points', 'got 1']),
            ('decreasing stamps', path_message(line, [1.0, 3.0, 2.0]),
             ['path point 2', 'is not after point 1']),
            ('an unknown frame', path_message(line, frame='no_such_frame'),
             ['no transform', 'no_such_frame']),
            ('no frame', path_message(line, frame=''), ['frame_id is empty']),
        ]
        for label, msg, words in cases:
            refused = int(self.diagnostic_value(CONTROLLER_STATUS, topic + ' refused') or 0)
            publish_when_connected(self.path_pub, msg)
            wait_until(lambda: int(self.diagnostic_value(CONTROLLER_STATUS, topic + ' refused')
                                   or 0) > refused, 'the controller to refuse the path with ' + label)
            reason = self.diagnostic_value(CONTROLLER_STATUS, topic + ' last refusal')
            rospy.loginfo('path with %s refused: %s', label, reason)
            for word in words:
                self.assertIn(word, reason, label)
            level, message = self.controller_level()
            self.assertEqual(level, DiagnosticStatus.WARN, message)
            self.assertIn('path refused', message)
            self.assertEqual(self.diagnostic_value(CONTROLLER_STATUS, 'path'), followed, label)
        self.assertEqual(self.desired_paths.count(), desired_paths, 'a refused path was shown')
        self.assert_nodes_alive()
        self.assertLess(self.errors.last().error_norm, 0.3)

    def test_03_a_path_in_another_frame_goes_through_tf_and_replaces_the_last(self):
        from geometry_msgs.msg import TransformStamped
        broadcaster = tf2_ros.StaticTransformBroadcaster()
        offset = TransformStamped()
        offset.header.frame_id = 'map'
        offset.child_frame_id = 'user_path_frame'
        offset.transform.translation.x, offset.transform.translation.y = 1.0, -0.5
        # a quarter turn about z: (x, y) -> (-y, x)
        offset.transform.rotation.z = offset.transform.rotation.w = math.sqrt(0.5)
        broadcaster.sendTransform(offset)
        shown = self.desired_paths.count()
        accepted = int(self.diagnostic_value(CONTROLLER_STATUS, rospy.resolve_name('path') + ' accepted'))
        publish_when_connected(self.path_pub, path_message([(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)],
                                                           frame='user_path_frame'))
        wait_until(lambda: self.desired_paths.count() > shown, 'the new path on desired_path')
        desired = self.desired_paths.last()
        self.assertEqual(desired.header.frame_id, self.prefix + 'odom')
        first, last = desired.poses[0].pose.position, desired.poses[-1].pose.position
        self.assertAlmostEqual(math.dist((first.x, first.y), (1.0, -0.5)), 0.0, delta=1e-9)
        self.assertAlmostEqual(math.dist((last.x, last.y), (1.0, 1.5)), 0.0, delta=1e-9)
        wait_until(lambda: 'user_path_frame' in (self.diagnostic_value(CONTROLLER_STATUS, 'path from') or ''),
                   'the new path on /diagnostics')
        self.assertEqual(int(self.diagnostic_value(CONTROLLER_STATUS,
                                                   rospy.resolve_name('path') + ' accepted')),
                         accepted + 1)


class SmoothnessCheck(StackFixture):
    """mode:=smoothness: issue 13's criteria on the set-points the controller sends (the default,
    smooth law): after 40 s of simulated time, until ~until [s] (100), consecutive
    actuators/command set-points of one actuator change sign (both above 0.01 rad/s) on fewer than
    ~max_sign_changes (0.01) of the steps, and change by no more than the hardware interface's
    max_acceleration allows over the time between them (at least the controller's 1/50 s). Then
    the law and gains reconfigured mid-run (test_02)."""

    FLOOR = 0.01  # [rad/s]
    PERIOD = 0.02  # [s] the controller's
    RECORDS_COMMANDS = True

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.max_acceleration = float(rospy.get_param('hardware_interface/max_acceleration'))

    def test_01_set_points_are_smooth(self):
        until = float(rospy.get_param('~until', 100.0))
        wait_until(lambda: self.errors.count() > 0, 'the first tracking_error message')
        start = self.errors.since(0)[0].header.stamp.to_sec()
        wait_until(lambda: self.commands.count() > 0 and
                   self.commands.last().header.stamp.to_sec() - start > until,
                   '%.0f s of simulated tracking' % until)
        steps = changes = 0
        worst = 0.0  # the largest change / what the acceleration limit allows
        messages = [m for m in self.commands.since(0) if m.header.stamp.to_sec() - start <= until]
        for before, now in zip(messages, messages[1:]):
            if now.header.stamp.to_sec() - start < SETTLE[0]:
                continue
            steps += 1
            allowed = self.max_acceleration * max(
                now.header.stamp.to_sec() - before.header.stamp.to_sec(), self.PERIOD)
            previous = dict(zip(before.name, before.velocity))
            flipped = False
            for name, rate in zip(now.name, now.velocity):
                old = previous.get(name, 0.0)
                flipped |= old * rate < 0.0 and abs(old) > self.FLOOR and abs(rate) > self.FLOOR
                worst = max(worst, abs(rate - old) / allowed)
            changes += flipped
        rospy.loginfo('set-points after %.0f s: %d sign changes in %d steps, largest change %.2f of '
                      'the acceleration limit', SETTLE[0], changes, steps, worst)
        self.assertGreater(steps, 1000)
        self.assertLess(changes, float(rospy.get_param('~max_sign_changes', 0.01)) * steps)
        self.assertLessEqual(worst, 1.0)

    def test_02_law_and_gains_reconfigured_mid_run(self):
        """dynamic_reconfigure mid-run (cfg/PurePursuitController.cfg), after test_01's window: the
        server starts from the loaded law and gains; switched to the paper law with new gains, every
        later command is eq 55's closed form with those gains, from the error the controller
        publishes at the same step; a NaN gain is refused and the last good gains handed back."""
        from dynamic_reconfigure.client import Client
        client = Client('pure_pursuit_controller', timeout=30.0)
        loaded = {k: v for k, v in client.get_configuration(timeout=10.0).items() if k != 'groups'}
        robot = rospy.get_param('pure_pursuit_controller/robot_type', '3R')
        self.assertEqual(robot, '3R', 'eq 55 below is the 3R law')
        self.assertEqual(loaded['law'], rospy.get_param('pure_pursuit_controller/law', 'smooth'))
        for key, value in rospy.get_param('terrain/smooth_gains/3R').items():
            self.assertEqual(loaded[key], float(value), 'the server must start from the loaded ' + key)
        self.assertEqual(loaded['k_e'], float(rospy.get_param('terrain/gains/k_e')))

        gains = {'k_theta': 1.5, 'k_phi1': 1.2, 'k_phi2': 0.1, 'k_psi': 0.6, 'k_e': 0.4}
        errors = Recorder('tracking_error', TrackingError)
        try:
            # The controller has worked at least to the last command this node has: the change
            # takes effect at a later step. Which one depends on when the call lands, so the
            # switch is found in the data: the first command from there that is eq 55 with the new
            # gains; every command after it must be too.
            before = self.commands.last().header.stamp.to_sec()
            client.update_configuration(dict(gains, law='paper'))
            wait_until(lambda: self.commands.last().header.stamp.to_sec() >= before + 3.0,
                       'commands up to %.1f s' % (before + 3.0))
            by_stamp = {m.header.stamp: m for m in errors.since(0)
                        if before < m.header.stamp.to_sec() <= before + 3.0}

            def eq55(error):  # signs per docs/conventions.md
                n = error.error_norm / (gains['k_e'] + error.error_norm)
                v = error.desired_velocity
                return {'theta': gains['k_theta'] * n * math.cos(error.zeta) +
                                 math.sqrt(v.x ** 2 + v.y ** 2 + v.z ** 2) / self.radius,
                        'phi': -(gains['k_phi1'] * n + gains['k_phi2']) * math.sin(error.zeta),
                        'psi': gains['k_psi'] * error.zeta}

            def is_eq55(command, expected):
                return all(abs(rate - expected[name]) <= 1e-9 * (1 + abs(rate))
                           for name, rate in zip(command.name, command.velocity))

            pairs = [(command, by_stamp[command.header.stamp]) for command in self.commands.since(0)
                     if command.header.stamp in by_stamp]
            switch = next((i for i, (command, error) in enumerate(pairs)
                           if is_eq55(command, eq55(error))), None)
            self.assertIsNotNone(switch, 'no command within 3 s after the change is eq 55 with the '
                                         'new gains')
            switched_at = pairs[switch][0].header.stamp.to_sec()
            self.assertLess(switched_at - before, 1.0, 'the change took effect %.2f s (simulated) '
                            'after the last command seen before it' % (switched_at - before))
            compared = 0
            for command, error in pairs[switch:]:
                expected = eq55(error)
                for name, rate in zip(command.name, command.velocity):
                    self.assertAlmostEqual(rate, expected[name], delta=1e-9 * (1 + abs(rate)),
                                           msg='%s at %.2f s' % (name, command.header.stamp.to_sec()))
                compared += 1
            self.assertGreater(compared, 50, 'commands compared with eq 55')

            kept = client.update_configuration({'k_theta': float('nan')})
            self.assertEqual(kept['k_theta'], gains['k_theta'], 'a NaN gain must be refused')
            self.assertEqual(kept['law'], 'paper')
            wait_until(lambda: 'k_theta' in (self.diagnostic_value(
                           CONTROLLER_STATUS, 'last refused reconfiguration') or ''),
                       'diagnostics to name the refused gain')
        finally:
            restored = client.update_configuration(loaded)
        self.assertEqual({k: restored[k] for k in loaded}, loaded)


class HeightMapCheck(StackFixture):
    """mode:=height_map: the stack on a height map (terrain:=FILE.yaml) draws the map's extent
    as the terrain mesh, names the map on /diagnostics and tracks as the batch run on the same
    map (~batch)."""

    def test_01_mesh_covers_the_map(self):
        mesh = rospy.wait_for_message('terrain_marker', Marker, timeout=30.0)
        xs, ys = [p.x for p in mesh.points], [p.y for p in mesh.points]
        extent = [float(v) for v in rospy.get_param('~extent')]  # x_min, x_max, y_min, y_max
        for got, want in zip((min(xs), max(xs), min(ys), max(ys)), extent):
            self.assertAlmostEqual(got, want, delta=1e-9)

    def test_02_diagnostics_name_the_map(self):
        wait_until(lambda: self.diagnostic_value(PLANT_STATUS, 'surface') is not None,
                   'the plant\'s surface on /diagnostics')
        surface = rospy.get_param('terrain/surface/height_map')
        image = os.path.join(os.path.dirname(surface), 'hills.png')
        self.assertIn('height map ' + image, self.diagnostic_value(PLANT_STATUS, 'surface'))

    def test_03_tracks_as_the_batch_run(self):
        assert_tracking(self, self.errors)


class OffMapCheck(StackFixture):
    """mode:=off_map (teleop on a height map, starting short of its +x edge ~edge [m]): driven
    off the map, the plant refuses every step that would leave it, holds its last state on the
    map, counts the failed steps on /diagnostics and goes on publishing."""

    def failed_steps(self):
        return int(self.diagnostic_value(PLANT_STATUS, 'integration failures') or 0)

    def test_01_held_at_the_edge(self):
        edge = float(rospy.get_param('~edge'))
        publish_until(rospy.Publisher('cmd_vel', Twist, queue_size=10),
                      [Twist(linear=Vector3(x=0.2))], lambda: self.failed_steps() > 0,
                      'the plant to report failed steps on /diagnostics')
        reached = max(m.contact_point.x for m in self.states.since(0))
        rospy.loginfo('off the map: the contact point reached x = %.4f m, the edge is at %g m',
                      reached, edge)
        self.assertLessEqual(reached, edge)
        self.assertGreater(reached, edge - 0.05)
        self.assert_nodes_alive()
        self.assert_still_publishing([self.odom, self.states])


class OdometryFeedbackCheck(StackFixture):
    """mode:=odometry: only standard messages reach the controller (issue 15 item 2), and they
    may come from another source than the plant. The test launch file remaps the plant's
    terrain_state to a topic nobody reads and gives the controller ~odom_topic (launch argument
    odom), which another node (~odom_source) publishes; by the master's own record the controller
    reads that topic (and, for RS, joint_states: the tilt) and no message of the plant's own
    type, and it still tracks: equal to the batch run (~batch), or within ~mean_bound and
    ~max_bound [m] over 40-60 s."""

    def test_01_controller_reads_standard_messages_only(self):
        import rosgraph
        controller = rospy.resolve_name('pure_pursuit_controller')
        odom_topic = rospy.resolve_name(rospy.get_param('~odom_topic', 'odom'))
        source = rospy.get_param('~odom_source', None)
        if source is not None:
            # topic_tools' relay advertises its output only with its first message
            master = rosgraph.Master(NAME)
            testing.wait_until(lambda: odom_topic in dict(master.getSystemState()[0]),
                               'a publisher of ' + odom_topic, 30.0)
        publishers, subscribers, _ = rosgraph.Master(NAME).getSystemState()
        read = sorted(topic for topic, nodes in subscribers if controller in nodes)
        types = dict(rosgraph.Master(NAME).getTopicTypes())
        rospy.loginfo('%s reads %s', controller, read)
        self.assertIn(odom_topic, read)
        self.assertEqual(types.get(odom_topic), 'nav_msgs/Odometry')
        if source is not None:
            self.assertEqual(dict(publishers)[odom_topic], [rospy.resolve_name(source)])
        if rospy.get_param('pure_pursuit_controller/robot_type') == 'RS':
            self.assertIn(rospy.resolve_name('joint_states'), read)
        for topic in read:
            self.assertNotEqual(types.get(topic), PKG + '/TerrainState', topic)
        # The plant's own message goes elsewhere: nothing publishes it here.
        self.assertNotIn(rospy.resolve_name('terrain_state'), dict(publishers))

    def test_02_tracking_converges(self):
        assert_tracking(self, self.errors)


class SensorsCheck(StackFixture):
    """mode:=sensors: the plant's seeded odometry noise and IMU (config/sensors_noisy.yaml, loaded
    into its private namespace): odom scatters about the true centre (terrain_state's, same
    stamp) with the configured deviation and claims it in its covariance; the IMU comes at its
    rate and reads gravity, +9.81 m/s^2 up, on average; the loop closed through this sensing still
    tracks, |e_t| over 40-60 s below ~mean_bound and ~max_bound [m]."""

    def test_01_odometry_scatters_as_configured(self):
        sigma = float(rospy.get_param('terrain_plant/noise/position'))
        wait_until(lambda: self.odom.count() >= 500, '500 odom messages')
        truth = {m.header.stamp: m.centre for m in self.states.since(0)}
        deviations = [getattr(m.pose.pose.position, a) - getattr(truth[m.header.stamp], a)
                      for m in self.odom.since(0) if m.header.stamp in truth for a in 'xyz']
        self.assertGreater(len(deviations), 1000)
        mean = sum(deviations) / len(deviations)
        deviation = math.sqrt(sum((d - mean) ** 2 for d in deviations) / len(deviations))
        rospy.loginfo('odom - truth: mean %.3g m, deviation %.4g m over %d components (sigma %g m)',
                      mean, deviation, len(deviations), sigma)
        self.assertLess(abs(mean), 4.0 * sigma / math.sqrt(len(deviations)))
        self.assertAlmostEqual(deviation, sigma, delta=0.1 * sigma)
        self.assertAlmostEqual(self.odom.last().pose.covariance[0], 1e-6 + sigma ** 2, delta=1e-12)

    def test_02_imu_reads_gravity(self):
        from sensor_msgs.msg import Imu
        rate = float(rospy.get_param('terrain_plant/imu_rate'))
        imu = Recorder('imu', Imu)
        wait_until(lambda: imu.count() >= 200, '200 imu messages')
        readings = imu.since(0)
        span = (readings[-1].header.stamp - readings[0].header.stamp).to_sec()
        self.assertAlmostEqual((len(readings) - 1) / span, rate, delta=0.01 * rate)
        self.assertEqual(readings[-1].header.frame_id, self.prefix + 'base_link')
        up = sum(m.linear_acceleration.z for m in readings) / len(readings)
        rospy.loginfo('imu: %d readings at %.1f Hz, mean specific force up %.4f m/s^2',
                      len(readings), (len(readings) - 1) / span, up)
        self.assertAlmostEqual(up, 9.81, delta=0.05)

    def test_03_tracking_through_noisy_odometry(self):
        assert_tracking(self, self.errors)


if __name__ == '__main__':
    rospy.init_node(NAME)
    mode = rospy.get_param('~mode', 'tracking')
    rostest.rosrun(PKG, NAME, {'teleop': TeleopCheck, 'seam': SeamCheck, 'roller': RollerCheck,
                               'norma': NormaCheck, 'height_map': HeightMapCheck,
                               'off_map': OffMapCheck, 'user_path': UserPathCheck,
                               'odometry': OdometryFeedbackCheck, 'sensors': SensorsCheck,
                               'smoothness': SmoothnessCheck}.get(mode, TrackingCheck))
