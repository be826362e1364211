#!/usr/bin/env python3
"""Sends a FreeBOT chain's default targets one after the other (launch/freebot_stack.launch).

Private params: ~targets (list of [x, y, z, qw, qx, qy, qz] in ~frame, or [x, y, z] for the
position only), ~frame (the chain's fixed base, <frame_prefix>link0; default link0), ~dwell [s]
simulated between a verdict and the next target, ~loop (false).
Publishes goal (geometry_msgs/PoseStamped) and waits for freebot_ik's verdict on goal_result
(arrived, unreachable, rejected or aborted) before the next one.
"""
import time

import rospy
from geometry_msgs.msg import PoseStamped

from spherical_robots.msg import FreebotGoalResult

FINAL = (FreebotGoalResult.ARRIVED, FreebotGoalResult.UNREACHABLE, FreebotGoalResult.REJECTED,
         FreebotGoalResult.ABORTED)


def pose_of(target, frame):
    if len(target) not in (3, 7):
        raise ValueError('a target is [x, y, z] or [x, y, z, qw, qx, qy, qz], got %r' % (target,))
    goal = PoseStamped()
    goal.header.frame_id = frame
    goal.pose.position.x, goal.pose.position.y, goal.pose.position.z = target[:3]
    if len(target) == 7:  # else all zero: position only
        o = goal.pose.orientation
        o.w, o.x, o.y, o.z = target[3:]
    return goal


def main():
    rospy.init_node('goal_sequence')
    frame = rospy.get_param('~frame', 'link0')
    goals = [pose_of(t, frame) for t in rospy.get_param('~targets')]
    dwell = float(rospy.get_param('~dwell', 2.0))
    loop = bool(rospy.get_param('~loop', False))
    verdicts = []
    rospy.Subscriber('goal_result', FreebotGoalResult,
                     lambda msg: verdicts.append(msg) if msg.status in FINAL else None)
    publisher = rospy.Publisher('goal', PoseStamped, queue_size=1)
    while not rospy.is_shutdown() and (rospy.Time.now().is_zero() or
                                       publisher.get_num_connections() == 0):
        time.sleep(0.1)  # the plant's clock and freebot_ik's subscription
    rospy.sleep(1.0)     # and freebot_ik's first chain state
    while not rospy.is_shutdown():
        for index, goal in enumerate(goals):
            count = len(verdicts)
            goal.header.stamp = rospy.Time.now()
            publisher.publish(goal)
            rospy.loginfo('target %d of %d: %s', index + 1, len(goals), goal.pose.position)
            while not rospy.is_shutdown() and len(verdicts) == count:
                rospy.sleep(0.1)
            if rospy.is_shutdown():
                return
            rospy.loginfo('target %d: %s', index + 1, verdicts[-1].message)
            rospy.sleep(dwell)
        if not loop:
            rospy.loginfo('all %d targets done', len(goals))
            rospy.spin()
            return


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
