#!/usr/bin/env python3
"""Sends a FreeBOT chain's default targets one after the other (launch/freebot_stack.launch).

Private params: ~targets (list of [x, y, z, qw, qx, qy, qz] in ~frame, or [x, y, z] for the
position only), ~frame (the chain's fixed base, <frame_prefix>link0; default link0), ~dwell [s]
simulated between a verdict and the next target, ~loop (false).
A client of freebot_ik's move_freebot action (spherical_robots/MoveFreebotAction): each target is
a goal, and the next one waits for its result (arrived, unreachable, rejected, preempted or
aborted).

In lock-step, listed in <ns>/lockstep/participants (the stack lists it before freebot_ik), it is a
participant of the loop (docs/lockstep.md, "The FreeBOT stack's goals"): it sends a goal at a
step, stamped with the step's time, which freebot_ik waits for and takes at that step, and it sees
a result at its first request after the step freebot_ik published it at, so two runs send the
same goals at the same steps. actionlib's clients stamp a goal with the node's clock, which lags
the step, so this node speaks the action's two topics itself: MoveFreebotActionGoal on
move_freebot/goal, with a goal id made of its name, the goal's number and the step's time, and
MoveFreebotActionResult from move_freebot/result. Outside lock-step it looks every 0.05 s of ROS
time.

A goal out when freebot_ik dies (killed, crashed) dies with it: the freebot_ik that roslaunch
restarts (respawn:=true) has never heard of it, and its result would never come. This node knows
the action's server by the URI the master has for the node publishing its results (a restarted
node registers under a new one) and sends the target again once a new server has been up (and
connected) for 1 s of wall time.
"""
import copy
import math
import threading
import time

import rosgraph
import rospy

from spherical_robots.msg import (LockstepAck, LockstepStep, MoveFreebotActionGoal,
                                  MoveFreebotActionResult, MoveFreebotGoal)

POLL = 0.05  # [s] simulated between looks at the results while a goal is out or waits


def goal_of(target, frame):
    if len(target) not in (3, 7) or not all(math.isfinite(float(v)) for v in target):
        raise ValueError('a target is [x, y, z] or [x, y, z, qw, qx, qy, qz] of finite numbers, '
                         'got %r' % (target,))
    goal = MoveFreebotGoal()
    goal.target.header.frame_id = frame
    pose = goal.target.pose
    pose.position.x, pose.position.y, pose.position.z = target[:3]
    if len(target) == 7:  # else all zero: position only
        o = pose.orientation
        o.w, o.x, o.y, o.z = target[3:]
    return goal


class GoalSequence:

    def __init__(self):
        frame = rospy.get_param('~frame', 'link0')
        self.goals = [goal_of(t, frame) for t in rospy.get_param('~targets')]
        if not self.goals:
            raise ValueError('parameter %s is empty' % rospy.resolve_name('~targets'))
        self.dwell = float(rospy.get_param('~dwell', 2.0))
        if not (math.isfinite(self.dwell) and self.dwell >= 0.0):
            raise ValueError('parameter %s: %r is not a finite number >= 0'
                             % (rospy.resolve_name('~dwell'), self.dwell))
        self.loop = bool(rospy.get_param('~loop', False))
        self.name = rospy.get_name()
        self.lock = threading.Lock()
        self.index = 0          # the target sent next
        self.sent = 0           # goals sent so far
        self.out = None         # the id of the goal sent whose result has not been taken
        self.send_at = 0.0      # [s] the earliest time of the next goal
        self.result = None      # the MoveFreebotActionResult of the goal out
        self.other_results = 0  # results of other goals: other clients', this node's lost ones
        self.server = ()        # the URIs of the action's server, () while none is connected
        self.server_since = 0.0  # [s] of wall time since self.server is what it is
        self.out_server = ()    # self.server when the goal out was sent
        self.goal_lost = False  # the server went away while a goal was out
        self.goal_pub = rospy.Publisher('move_freebot/goal', MoveFreebotActionGoal, queue_size=10,
                                        tcp_nodelay=True)
        self.result_sub = rospy.Subscriber('move_freebot/result', MoveFreebotActionResult,
                                           self.on_result, queue_size=100, tcp_nodelay=True)
        participants = rospy.get_param('lockstep/participants', [])
        self.lockstep = self.name in [rospy.names.ns_join(rospy.get_namespace(), name)
                                      for name in participants]
        if self.lockstep:
            self.pending = None         # the stamp of the request not yet worked
            self.result_listed = None   # the latest result stamp a request listed [ns]
            self.awaiting = None        # other_results when a listed result began to be awaited
            self.last_request_wall = None
            self.ack_pub = rospy.Publisher('lockstep/ack', LockstepAck, queue_size=100,
                                           tcp_nodelay=True)
            rospy.Subscriber('~lockstep/step', LockstepStep, self.on_step, queue_size=100,
                             tcp_nodelay=True)
        else:
            rospy.Timer(rospy.Duration(POLL), self.on_timer)
        threading.Thread(target=self.watch_server, daemon=True).start()

    def connected(self):
        """freebot_ik reads the goals and publishes the results (the action server is up)."""
        return self.goal_pub.get_num_connections() > 0 and self.result_sub.get_num_connections() > 0

    def server_up(self):
        """With the lock held: the same server has been connected for 1 s of wall time (long
        enough for a restarted one to have subscribed to the goals)."""
        return bool(self.server) and time.time() - self.server_since >= 1.0

    def server_uris(self, master):
        """The URIs of the nodes publishing the action's results: a node that roslaunch restarts
        registers under a new one (rospy can keep counting a connection to a dead publisher while it
        retries it, so the connection count alone can miss a restart)."""
        publishers = dict(master.getSystemState()[0]).get(self.result_sub.resolved_name, [])
        return tuple(sorted(master.lookupNode(node) for node in publishers))

    def watch_server(self):
        """Every 0.25 s of wall time: which server is connected, and since when; a goal out when
        its server has gone is lost. In lock-step, asks to join once the server is up, until a
        request comes, and again after 1 s without one."""
        master = rosgraph.Master(self.name)
        while not rospy.is_shutdown():
            time.sleep(0.25)
            try:
                server = self.server_uris(master) if self.connected() else ()
            except (rosgraph.MasterError, OSError):  # the master is going away at the end
                continue
            with self.lock:
                if server != self.server:
                    self.server, self.server_since = server, time.time()
                if self.out is not None and self.server != self.out_server:
                    self.goal_lost = True
                join = self.lockstep and self.server_up() and (
                    self.last_request_wall is None or time.time() - self.last_request_wall > 1.0)
            if join:
                self.ack_pub.publish(LockstepAck(participant=self.name))

    # --- lock-step (docs/lockstep.md) -------------------------------------------------------------

    def on_step(self, request):
        if request.participant != self.name:
            return
        with self.lock:
            self.last_request_wall = time.time()
            for topic, stamp in zip(request.inputs, request.input_stamps):
                if topic == self.result_sub.resolved_name and (
                        self.result_listed is None or stamp.to_nsec() > self.result_listed):
                    # freebot_ik ended a goal at that step: this node's, while one is out
                    self.result_listed = stamp.to_nsec()
                    if self.out is not None:
                        self.awaiting = self.other_results
            self.pending = request.stamp
            self.work_if_ready()

    def work_if_ready(self):
        """With the lock held: the pending step's work, once a listed result has come (this
        goal's; another client's goal's result also ends the wait, that client having broken
        repeatability anyway). A result of this node's goal that no request lists (freebot_ik
        rejected it on arrival, outside a step: a bad ~frame) is taken at the next step too."""
        if self.pending is None:
            return
        if (self.awaiting is not None and self.result is None
                and self.other_results == self.awaiting):
            return
        self.awaiting = None
        stamp, self.pending = self.pending, None
        published, next_time = self.work(stamp, self.result is not None)
        self.ack_pub.publish(LockstepAck(stamp=stamp, participant=self.name, published=published,
                                         next=next_time))

    # --- both times -------------------------------------------------------------------------------

    def on_result(self, msg):
        with self.lock:
            if self.out is not None and msg.status.goal_id.id == self.out:
                self.result = msg
            else:
                self.other_results += 1
            if self.lockstep:
                self.work_if_ready()

    def on_timer(self, _event):
        now = rospy.Time.now()
        with self.lock:
            if not now.is_zero():
                self.work(now, self.result is not None)

    def work(self, stamp, ended):
        """At step time `stamp`: takes the result of the goal out if `ended`, sends the next goal
        when due. Returns the topics published and the time of the next look."""
        t = stamp.to_sec()
        if ended:
            rospy.loginfo('target %d: %s', self.index + 1,
                          self.result.result.message or self.result.status.text)
            self.out = self.result = None
            self.goal_lost = False
            self.index += 1
            self.send_at = t + self.dwell
            if self.index == len(self.goals):
                rospy.loginfo('all %d targets done', len(self.goals))
                if self.loop:
                    self.index = 0
        elif self.goal_lost and self.server_up():
            rospy.logwarn('target %d: freebot_ik went away while driving to it; sending it again',
                          self.index + 1)
            self.out = None
            self.goal_lost = False
        published = []
        if (self.out is None and self.index < len(self.goals) and t >= self.send_at
                and self.server_up()):
            self.send(stamp)
            published.append(self.goal_pub.resolved_name)
        waits = self.out is None and self.index < len(self.goals)
        next_time = min(self.send_at, t + POLL) if waits else t + POLL
        return published, rospy.Time.from_sec(max(next_time, t))

    def send(self, stamp):
        self.sent += 1
        msg = MoveFreebotActionGoal()
        msg.header.stamp = msg.goal_id.stamp = stamp
        msg.goal_id.id = '%s-%d-%d' % (self.name, self.sent, stamp.to_nsec())
        msg.goal = copy.deepcopy(self.goals[self.index])
        msg.goal.target.header.stamp = stamp
        self.out = msg.goal_id.id
        self.out_server = self.server
        self.goal_pub.publish(msg)
        rospy.loginfo('target %d of %d: %s', self.index + 1, len(self.goals),
                      msg.goal.target.pose.position)


def main():
    rospy.init_node('goal_sequence')
    try:
        GoalSequence()
    except ValueError as error:
        rospy.logfatal('goal_sequence: %s', error)
        raise SystemExit(2)
    rospy.spin()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
