#!/usr/bin/env python3
"""Sends a FreeBOT chain's default targets one after the other (launch/freebot_stack.launch).

Private params: ~targets (list of [x, y, z, qw, qx, qy, qz] in ~frame, or [x, y, z] for the
position only), ~frame (the chain's fixed base, <frame_prefix>link0; default link0), ~dwell [s]
simulated between a verdict and the next target, ~loop (false).
A client of freebot_ik's move_freebot action (spherical_robots/MoveFreebotAction): each target is
a goal, and the next one waits for its result (arrived, unreachable, rejected or aborted).
"""
import time

import actionlib
import rospy

from spherical_robots.msg import MoveFreebotAction, MoveFreebotGoal


def goal_of(target, frame):
    if len(target) not in (3, 7):
        raise ValueError('a target is [x, y, z] or [x, y, z, qw, qx, qy, qz], got %r' % (target,))
    goal = MoveFreebotGoal()
    goal.target.header.frame_id = frame
    pose = goal.target.pose
    pose.position.x, pose.position.y, pose.position.z = target[:3]
    if len(target) == 7:  # else all zero: position only
        o = pose.orientation
        o.w, o.x, o.y, o.z = target[3:]
    return goal


def main():
    rospy.init_node('goal_sequence')
    frame = rospy.get_param('~frame', 'link0')
    goals = [goal_of(t, frame) for t in rospy.get_param('~targets')]
    dwell = float(rospy.get_param('~dwell', 2.0))
    loop = bool(rospy.get_param('~loop', False))
    client = actionlib.SimpleActionClient('move_freebot', MoveFreebotAction)
    while not rospy.is_shutdown() and rospy.Time.now().is_zero():
        time.sleep(0.1)  # the plant's clock
    client.wait_for_server()
    while not rospy.is_shutdown():
        for index, goal in enumerate(goals):
            goal.target.header.stamp = rospy.Time.now()
            client.send_goal(goal)
            rospy.loginfo('target %d of %d: %s', index + 1, len(goals), goal.target.pose.position)
            client.wait_for_result()
            if rospy.is_shutdown():
                return
            result = client.get_result()
            rospy.loginfo('target %d: %s', index + 1,
                          result.message if result else client.get_goal_status_text())
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
