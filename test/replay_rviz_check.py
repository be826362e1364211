#!/usr/bin/env python3
"""rostest of launch/replay.launch: rviz under Xvfb shows a replayed stack's bag
(test/replay_rviz.test: terrain; test/replay_rviz_{roller,norma,rotor,freebot}.test).

The bag (test/data/*_fixture.bag, test/make_fixture_bag.sh) plays in a loop at ~rate x. Private
params: ~ns (the stack's namespace, sphere), ~rviz_config, ~robot_frames (the frames whose spheres
must show: [<ns>/base_link]), ~robot_radius (their radius, 0.2 m), ~robot_reference ("ring": the
robot is judged against the scene around it, for a terrain; "background": against the panel's
plain background colour), ~min_terrain_fraction (0.2; 0 for a stack without a terrain mesh),
~min_path_pixels (300), ~min_trail_pixels (80), ~shot_window ([12, 22] s of bag time), ~bag (the
bag played). Checks:
  1. /<ns>/rviz subscribes to every topic its rviz config names (tf, tf_static, terrain_marker,
     desired_path, trail, planned_path, freebot_markers, ...): only the config names these, so
     the config was loaded;
  2. a screenshot (`import -window root`) taken in the shot window of a pass, in its 3D panel:
     not blank (the terrain's colours cover a good part of it), the desired (or planned) path's
     colour and the driven trail's colour of the stack's rviz config, and the robot's colours
     inside the disc where /tf puts each robot frame, and far fewer elsewhere;
  3. rviz is rendering live: a second screenshot differs from the first;
  4. after the bag loops (simulated time jumps back to its start), the same screenshot checks pass
     again: rviz cleared its tf buffer and redrew from the replayed messages, no stale tf;
  5. a subscriber to /tf_static that comes once the bag plays still gets every static transform of
     the bag (rosbag play latches only the last /tf_static message; scripts/replay_latched.py
     offers them merged);
  6. no ERROR from rviz on /rosout (rostest runs no rosout node, hence no /rosout_agg; what rviz
     logs before this node subscribes, in its first second, is not seen). The jump's "Detected
     jump back in time ... Clearing TF buffer" WARN is expected and counted.
A robot frame is located by projecting its tf position with the Orbit camera of the rviz config
(distance, yaw, pitch, focal point, vertical field of view) onto the 3D panel, which is found as
the bounding box of the background colour. Robot colours: a translucent blue shell (blue over red
by > 25 more than the reference has) or, for the terrain robots, their orange band seen through
it. With the "ring" reference the scene is the mean colour of a ring around the disc, and the
controls are discs of the same size around it; with "background", the controls are the rest of
the panel, outside every robot disc. Screenshots are saved in $ROS_HOME (printed). Deadlines are
wall-clock and generous (slow CI); a pass of a 25 s bag at rate 2 is about 12 s of wall time.
"""
import math
import os
import subprocess
import threading
import time
import unittest

import numpy as np
import rosbag
import rosgraph
import rosgraph.names
import rospy
import rostest
import yaml
from rosgraph_msgs.msg import Clock
from rosgraph_msgs.msg import Log
from tf2_msgs.msg import TFMessage

from spherical_robots_testing import wait_until

PKG = 'spherical_robots'
NAME = 'replay_rviz_check'
STARTUP_DEADLINE = 90.0     # [s] wall: rviz up and subscribed
PASS_DEADLINE = 90.0        # [s] wall: reaching a given point of a pass of the bag
MIN_CHANGED_PIXELS = 200    # between two shots 1 s apart
MAX_RVIZ_RESTARTS = 2
# [s] wall: a new /tf_static subscription connected and served by the latched publishers. 5 s
# ran out once with four tests, rviz and two busy loops on two cores.
LATCH_WAIT = 20.0
MIN_ROBOT_PIXELS = 40       # robot-coloured pixels in its disc (terrain: ~15 px radius; 50-400)
MIN_ROBOT_FRACTION = 0.5    # of its disc, against a plain background (measured: rotor 0.67-0.68, FreeBOT
                            # 0.93-0.95; half a radius off: 0.39 and 0.12-0.35)


class Settings:
    """The stack's private parameters (see the module's docstring); defaults: the terrain stack.
    Colour classes [RGB 0-255] in the 3D panel, measured counts in the test's log: desired path
    25;255;0 (terrain: a 0.02 m line around a 2 m circle, ~900 px), driven trail 255;220;0 (terrain:
    0.03 m line, 12+ s of it, ~270 px), terrain mesh (about half of the panel)."""

    def __init__(self):
        self.ns = rospy.get_param('~ns', 'sphere')
        self.rviz = '/%s/rviz' % self.ns
        self.robot_frames = rospy.get_param('~robot_frames', ['%s/base_link' % self.ns])
        self.robot_radius = float(rospy.get_param('~robot_radius', 0.2))
        self.robot_reference = rospy.get_param('~robot_reference', 'ring')
        if self.robot_reference not in ('ring', 'background'):
            raise ValueError('~robot_reference must be "ring" or "background", not %r'
                             % self.robot_reference)
        self.min_terrain_fraction = float(rospy.get_param('~min_terrain_fraction', 0.2))
        self.min_path_pixels = int(rospy.get_param('~min_path_pixels', 300))
        self.min_trail_pixels = int(rospy.get_param('~min_trail_pixels', 80))
        self.shot_window = tuple(rospy.get_param('~shot_window', [12.0, 22.0]))


S = None  # Settings, made in main


def rviz_config():
    with open(rospy.get_param('~rviz_config')) as f:
        return yaml.safe_load(f)


def grab_screen():
    """The X root window as an H x W x 3 int array, via ImageMagick's import (PPM)."""
    data = subprocess.run(['import', '-window', 'root', '-depth', '8', 'ppm:-'], check=True,
                          capture_output=True, timeout=30).stdout
    magic, size, maxval, pixels = data.split(b'\n', 3)
    if magic != b'P6' or maxval != b'255':
        raise AssertionError('unexpected screenshot format %r %r' % (magic, maxval))
    width, height = map(int, size.split())
    return np.frombuffer(pixels[:width * height * 3], np.uint8).reshape(height, width, 3), data


class OrbitCamera:
    """rviz's Orbit view (OrbitViewController): the eye sits at `distance` from the focal point at
    (yaw, pitch), looks at it with world z up; perspective with a vertical field of view."""

    def __init__(self, view):
        self.focal = np.array([view['Focal Point'][k] for k in ('X', 'Y', 'Z')], float)
        yaw, pitch, distance = view['Yaw'], view['Pitch'], view['Distance']
        self.eye = self.focal + distance * np.array(
            [math.cos(yaw) * math.cos(pitch), math.sin(yaw) * math.cos(pitch), math.sin(pitch)])
        self.forward = (self.focal - self.eye) / np.linalg.norm(self.focal - self.eye)
        right = np.cross(self.forward, [0.0, 0.0, 1.0])
        self.right = right / np.linalg.norm(right)
        self.up = np.cross(self.right, self.forward)
        self.tan_half_fov = math.tan(view['Field of View'] / 2.0)

    def project(self, point, panel):
        """Pixel (column, row) of a world point in the panel (top, bottom, left, right)."""
        top, bottom, left, right = panel
        width, height = right - left + 1, bottom - top + 1
        v = np.asarray(point, float) - self.eye
        depth = v @ self.forward
        x = (v @ self.right) / (depth * self.tan_half_fov * width / height)
        y = (v @ self.up) / (depth * self.tan_half_fov)
        return left + (x + 1.0) / 2.0 * width, top + (1.0 - y) / 2.0 * height


def find_panel(image, background):
    """The 3D panel: bounding box of the rows and columns with many background-coloured pixels
    (the Displays panel's small colour swatch has the same colour but few pixels)."""
    bg = np.all(image == np.array(background, np.uint8), axis=2)
    rows = np.nonzero(bg.sum(axis=1) >= 40)[0]
    cols = np.nonzero(bg.sum(axis=0) >= 40)[0]
    if len(rows) == 0 or len(cols) == 0:
        return None
    return rows.min(), rows.max(), cols.min(), cols.max()


def colour_classes(p):
    """Boolean masks over an H x W x 3 int array."""
    r, g, b = p[..., 0], p[..., 1], p[..., 2]
    path = (g > 200) & (r < 100) & (b < 60)                                   # 25;255;0
    trail = (r > 200) & (g > 170) & (g < 240) & (b < 50) & (r - g > 15)       # 255;220;0
    # eq 59 terrain mesh (conversions::surfaceMesh): green to yellow, never r > g + 10 or b > g
    terrain = (g >= r - 10) & (g > b + 15) & ~path & ~trail
    return path, trail, terrain


def robot_coloured(pixels, reference):
    """Robot colours among N x 3 int pixels, against a reference colour (what is behind the robot):
    the translucent blue shell raises blue over red (b - r up by > 25); the terrain robots' orange
    band seen through it is orange (r > g + 20, g > b + 15, and not the trail's yellow). The
    terrain or the background alone is neither."""
    diff = pixels - reference
    shell = (diff[..., 2] - diff[..., 0]) > 25
    r, g, b = pixels[..., 0], pixels[..., 1], pixels[..., 2]
    band = (r > g + 20) & (g > b + 15) & ~((b < 50) & (g > 170))
    return shell | band


def map_position(transforms, frame, fixed='map'):
    """Position of `frame` in `fixed` through the chain of latest transforms {child: (parent,
    translation, rotation xyzw)}; None if the chain does not reach `fixed`."""
    position = np.zeros(3)
    for _ in range(len(transforms) + 1):
        if frame == fixed:
            return position
        if frame not in transforms:
            return None
        frame, translation, (x, y, z, w) = transforms[frame]
        u = np.array([x, y, z])  # rotate by the unit quaternion: v + 2w(u x v) + 2u x (u x v)
        position = (translation + position + 2.0 * w * np.cross(u, position)
                    + 2.0 * np.cross(u, np.cross(u, position)))
    return None


def disc_distance(shape, centre):
    """Distance [px] of every pixel of an image of `shape` from `centre` (column, row)."""
    yy, xx = np.mgrid[0:shape[0], 0:shape[1]]
    return np.hypot(xx - centre[0], yy - centre[1])


def robot_pixels(image, centre, radius):
    """Robot-coloured pixels in the disc of `radius` px around `centre`, judged against the mean of
    a ring around it (the terrain there)."""
    cx, cy = centre
    h, w = image.shape[:2]
    reach = int(radius * 2.6) + 2
    y0, y1 = max(0, int(cy) - reach), min(h, int(cy) + reach + 1)
    x0, x1 = max(0, int(cx) - reach), min(w, int(cx) + reach + 1)
    patch = image[y0:y1, x0:x1].astype(int)
    d = disc_distance(patch.shape, (cx - x0, cy - y0))
    disc, ring = d <= radius, (d > 1.6 * radius) & (d < 2.6 * radius)
    if disc.sum() == 0 or ring.sum() == 0:
        return 0
    return int(robot_coloured(patch[disc], patch[ring].mean(axis=0)).sum())


class ReplayRvizCheck(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.lock = threading.Lock()
        cls.transforms = {}      # child frame -> (parent frame, translation, rotation xyzw), latest
        cls.clock = None
        cls.jumps = 0            # times simulated time went back (bag loops)
        cls.rviz_errors = []
        cls.restarts = 0         # of an rviz that hung at start-up (restart_rviz)
        cls.rviz_warnings = []
        config = rviz_config()
        cls.background = [int(c) for c in
                          config['Visualization Manager']['Global Options']['Background Color'].split(';')]
        cls.camera = OrbitCamera(config['Visualization Manager']['Views']['Current'])
        cls.topics = sorted(
            rosgraph.names.ns_join('/' + S.ns, d[key])
            for d in config['Visualization Manager']['Displays']
            for key in ('Topic', 'Marker Topic') if key in d and d.get('Enabled', True))
        cls.shot_dir = os.environ.get('ROS_HOME', os.path.expanduser('~/.ros'))
        rospy.Subscriber('/tf', TFMessage, cls.on_tf, queue_size=100)
        rospy.Subscriber('/tf_static', TFMessage, cls.on_tf, queue_size=100)
        rospy.Subscriber('/clock', Clock, cls.on_clock, queue_size=100)
        # rostest starts no rosout node, so there is no /rosout_agg: listen to /rosout itself.
        rospy.Subscriber('/rosout', Log, cls.on_log, queue_size=1000)

    @classmethod
    def on_tf(cls, msg):
        with cls.lock:
            for t in msg.transforms:
                v, q = t.transform.translation, t.transform.rotation
                cls.transforms[t.child_frame_id] = (t.header.frame_id, np.array([v.x, v.y, v.z]),
                                                    np.array([q.x, q.y, q.z, q.w]))

    @classmethod
    def on_clock(cls, msg):
        with cls.lock:
            t = msg.clock.to_sec()
            if cls.clock is not None and t < cls.clock - 1.0:
                cls.jumps += 1
            cls.clock = t

    @classmethod
    def on_log(cls, msg):
        if msg.name == S.rviz:
            if msg.level >= Log.ERROR:
                cls.rviz_errors.append(msg.msg)
            elif msg.level == Log.WARN:
                cls.rviz_warnings.append(msg.msg)

    def bag_time(self):
        with self.lock:
            return self.clock if self.clock is not None else -1.0

    def robot_positions(self):
        """World position of every robot frame from the latest transforms, None for a frame whose
        chain of transforms does not reach the fixed frame."""
        with self.lock:
            return [map_position(self.transforms, frame) for frame in S.robot_frames]

    def wait_for_shot_window(self, min_jumps):
        """Waits for bag time inside the shot window in a pass after `min_jumps` loops."""
        wait_until(lambda: self.jumps >= min_jumps
                   and S.shot_window[0] <= self.bag_time() <= S.shot_window[1],
                   'bag time in [%g, %g] s after %d loop(s)' % (S.shot_window + (min_jumps,)),
                   PASS_DEADLINE)

    def shot(self, label):
        """A screenshot with the robot frames' positions from /tf just before and after it, saved
        as replay_rviz_<config>_<label>.png (the replay tests share a ROS_HOME)."""
        before, t_before = self.robot_positions(), self.bag_time()
        image, ppm = grab_screen()
        after, t_after = self.robot_positions(), self.bag_time()
        config = os.path.splitext(os.path.basename(rospy.get_param('~rviz_config')))[0]
        path = os.path.join(self.shot_dir, 'replay_rviz_%s_%s.png' % (config, label))
        subprocess.run(['convert', 'ppm:-', path], input=ppm, check=True, timeout=30)
        rospy.loginfo('%s: screenshot %s taken at bag time %.2f-%.2f s', NAME, path, t_before,
                      t_after)
        robots = [None if b is None or a is None else (b + a) / 2.0 for b, a in zip(before, after)]
        return image, robots, path

    def shot_of_panel(self, label, min_jumps):
        """A shot in the shot window of a pass after `min_jumps` loops once rviz shows its 3D
        panel. On a loaded machine rviz may not have painted it by the first window (a black or
        half-drawn window): later passes are tried until PASS_DEADLINE, since what is tested is
        the picture, not how soon a busy machine draws it. Every try is logged."""
        deadline = time.time() + PASS_DEADLINE
        while True:
            self.wait_for_shot_window(min_jumps)
            image, robots, path = self.shot(label)
            if find_panel(image, self.background) is not None or time.time() > deadline:
                return image, robots, path
            if not image.any() and self.restarts < MAX_RVIZ_RESTARTS:
                self.restart_rviz(path)
                deadline = time.time() + PASS_DEADLINE
            else:
                rospy.logwarn('%s: no 3D panel yet in %s; trying the next pass', NAME, path)
            min_jumps = self.jumps + 1

    def restart_rviz(self, path):
        """rviz (1.14 with Mesa's llvmpipe under Xvfb) now and then hangs for good in its OpenGL
        set-up, before it maps any window: the screen stays black (2 of the 15 rviz starts of three
        runs of the suite on a machine loaded by two busy loops; its log stops at "Forcing OpenGl
        version 0."). That is rviz's start-up, not the replay under test: end it (SIGKILL,
        a hung process ignores a shutdown request); the test launches it with respawn_rviz, so
        roslaunch starts a new one."""
        import signal
        import xmlrpc.client
        self.restarts += 1
        uri = rosgraph.Master(NAME).lookupNode(S.rviz)
        pid = xmlrpc.client.ServerProxy(uri).getPid(NAME)[2]
        rospy.logwarn('%s: the screen is black in %s: rviz (pid %d) has not drawn its window; '
                      'restarting it (%d of %d)', NAME, path, pid, self.restarts, MAX_RVIZ_RESTARTS)
        os.kill(pid, signal.SIGKILL)

    def check_shot(self, image, robots, path):
        panel = find_panel(image, self.background)
        self.assertIsNotNone(panel, 'no 3D panel (background %s) in %s' % (self.background, path))
        top, bottom, left, right = panel
        self.assertGreater(right - left, 300, 'the 3D panel is too narrow: %s in %s' % (panel, path))
        self.assertGreater(bottom - top, 300, 'the 3D panel is too low: %s in %s' % (panel, path))
        p = image[top:bottom + 1, left:right + 1].astype(int)
        path_px, trail_px, terrain_px = (int(m.sum()) for m in colour_classes(p))
        terrain_fraction = terrain_px / float(p.shape[0] * p.shape[1])
        rospy.loginfo('%s: %s: panel rows %d-%d cols %d-%d; path %d px, trail %d px, terrain %.2f '
                      'of the panel', NAME, os.path.basename(path), top, bottom, left, right,
                      path_px, trail_px, terrain_fraction)
        self.assertGreaterEqual(terrain_fraction, S.min_terrain_fraction,
                                'blank 3D panel? terrain covers %.2f of it in %s'
                                % (terrain_fraction, path))
        self.assertGreaterEqual(path_px, S.min_path_pixels, 'desired path missing in %s' % path)
        self.assertGreaterEqual(trail_px, S.min_trail_pixels, 'driven trail missing in %s' % path)
        discs = []
        for frame, robot in zip(S.robot_frames, robots):
            self.assertIsNotNone(robot, 'no %s on /tf' % frame)
            centre = self.camera.project(robot, panel)
            # The sphere's radius on the image: the farthest of its six axis points from its
            # centre's. The point above it alone is foreshortened under a camera that looks down
            # (the rotor view, pitch 1.1 rad), and the shell outside that smaller disc counted as
            # robot colour away from the robot (0.108 of the panel, over its 0.1 limit, once).
            radius = max(math.hypot(rim[0] - centre[0], rim[1] - centre[1]) for rim in (
                self.camera.project(robot + S.robot_radius * axis, panel)
                for axis in np.vstack([np.eye(3), -np.eye(3)])))
            discs.append((frame, robot, centre, radius))
        if S.robot_reference == 'ring':
            self.check_robots_against_ring(image, discs, path)
        else:
            self.check_robots_against_background(image, panel, discs, path)

    def check_robots_against_ring(self, image, discs, path):
        for frame, robot, centre, radius in discs:
            on_robot = robot_pixels(image, centre, radius)
            controls = [robot_pixels(image, (centre[0] + 4 * radius * math.cos(a),
                                             centre[1] + 4 * radius * math.sin(a)), radius)
                        for a in np.linspace(0.0, 2.0 * math.pi, 8, endpoint=False)]
            rospy.loginfo('%s: %s at (%.3f, %.3f, %.3f) m -> px (%.0f, %.0f), r %.1f px: %d '
                          'robot-coloured px, controls %s', NAME, frame, robot[0], robot[1],
                          robot[2], centre[0], centre[1], radius, on_robot, controls)
            self.assertGreater(on_robot, MIN_ROBOT_PIXELS, '%s not where tf puts it (px %.0f, %.0f) '
                               'in %s' % ((frame,) + centre + (path,)))
            self.assertGreater(on_robot, 3 * sorted(controls)[len(controls) // 2] + 10,
                               '%s colours no more frequent at the robot than elsewhere in %s'
                               % (frame, path))

    def check_robots_against_background(self, image, panel, discs, path):
        top, bottom, left, right = panel
        p = image[top:bottom + 1, left:right + 1].astype(int)
        coloured = robot_coloured(p, np.array(self.background))
        near_any = np.zeros(coloured.shape, bool)
        for frame, robot, centre, radius in discs:
            d = disc_distance(coloured.shape, (centre[0] - left, centre[1] - top))
            disc = d <= 0.8 * radius  # inside the rim, whose shading is dark
            near_any |= d <= 1.3 * radius
            fraction = coloured[disc].mean() if disc.any() else 0.0
            rospy.loginfo('%s: %s at (%.3f, %.3f, %.3f) m -> px (%.0f, %.0f), r %.1f px: %.2f of '
                          'its disc robot-coloured', NAME, frame, robot[0], robot[1], robot[2],
                          centre[0], centre[1], radius, fraction)
            self.assertGreater(fraction, MIN_ROBOT_FRACTION, '%s not where tf puts it (px %.0f, '
                               '%.0f) in %s' % ((frame,) + centre + (path,)))
        elsewhere = coloured[~near_any].mean()
        rospy.loginfo('%s: %.3f of the panel away from the robot is robot-coloured', NAME, elsewhere)
        self.assertLess(elsewhere, MIN_ROBOT_FRACTION / 5.0,
                        'robot colours all over the panel in %s' % path)

    def test_01_config_loaded(self):
        self.assertGreaterEqual(len(self.topics), 2, 'rviz config without topics: %s' % self.topics)
        master = rosgraph.Master(NAME)

        def missing():
            subscribed = {topic for topic, nodes in master.getSystemState()[1] if S.rviz in nodes}
            return [t for t in ['/tf', '/tf_static'] + self.topics if t not in subscribed]
        wait_until(lambda: not missing(), '%s to subscribe to the topics of its config' % S.rviz,
                   STARTUP_DEADLINE)
        self.assertTrue(rospy.has_param('/%s/robot_description' % S.ns))

    def test_02_screenshot(self):
        wait_until(lambda: all(p is not None for p in self.robot_positions()), 'the robot on /tf', STARTUP_DEADLINE)
        # rviz needs a moment after subscribing to draw; a pass that began before it was up is
        # fine too, as long as the shot falls in the window.
        time.sleep(3.0)
        image, robots, path = self.shot_of_panel('first_pass', 0)
        self.check_shot(image, robots, path)
        time.sleep(1.0)
        image2, _, _ = self.shot('one_second_later')
        changed = int(np.any(image != image2, axis=2).sum())
        rospy.loginfo('%s: %d pixels changed in 1 s', NAME, changed)
        self.assertGreater(changed, MIN_CHANGED_PIXELS, 'rviz is not rendering live')

    def test_03_after_loop(self):
        image, robots, path = self.shot_of_panel('after_loop', self.jumps + 1)
        self.check_shot(image, robots, path)

    def test_04_late_subscriber_gets_every_static_transform(self):
        """What a subscription made now receives from latched publishers, before the bag loops
        (at a loop rosbag publishes /tf_static again, which would hide a missing latch): tried
        again on a new subscription if a loop comes first."""
        with rosbag.Bag(rospy.get_param('~bag')) as bag:
            recorded = {(t.header.frame_id, t.child_frame_id)
                        for _, msg, _ in bag.read_messages(topics=['/tf_static'])
                        for t in msg.transforms}
        self.assertGreater(self.bag_time(), 1.0, 'the bag has not played past its first second')
        for attempt in range(3):
            received = set()
            lock = threading.Lock()
            jumps = self.jumps

            def on_static(msg):
                with lock:
                    if self.jumps == jumps:
                        received.update((t.header.frame_id, t.child_frame_id)
                                        for t in msg.transforms)

            def all_received():
                with lock:
                    return recorded <= received
            subscriber = rospy.Subscriber('/tf_static', TFMessage, on_static, queue_size=100)
            try:
                wait_until(lambda: all_received() or self.jumps != jumps,
                           'every static transform of the bag %s on a new /tf_static '
                           'subscription' % sorted(recorded), LATCH_WAIT)
            finally:
                subscriber.unregister()
            rospy.loginfo('%s: a late /tf_static subscriber got %s (attempt %d)', NAME,
                          sorted(received), attempt + 1)
            if all_received():
                return
        self.fail('the bag looped during each of 3 attempts')

    def test_05_no_rviz_errors(self):
        time.sleep(1.0)  # let /rosout catch up
        jumps = [w for w in self.rviz_warnings if 'jump back in time' in w]
        rospy.loginfo('%s: %d loops seen on /clock; rviz warned %d times of a jump back in time',
                      NAME, self.jumps, len(jumps))
        self.assertEqual(self.rviz_errors, [], 'rviz logged errors')


if __name__ == '__main__':
    rospy.init_node(NAME)
    S = Settings()
    rostest.rosrun(PKG, NAME, ReplayRvizCheck)
