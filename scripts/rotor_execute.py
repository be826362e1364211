#!/usr/bin/env python3
"""Plans and executes one manoeuvre of the two-rotor sphere (launch/rotor_stack.launch).

A client of rotor_planner's execute_manoeuvre action (spherical_robots/ExecuteRotorManoeuvreAction):
sends ~k, ~steps, ~target ("u,v,psi": metres, metres, rad), ~max_radius [m] (0: the planner's)
and ~index (0 = the shortest plan), logs the feedback once a second and the result, and exits 0
when the manoeuvre was executed (the result's distance and heading error say where the sphere
rests), 1 otherwise (no plan, rejected, preempted, aborted: the result's message says why).
"""
import sys

import actionlib
import rospy

from spherical_robots.msg import (ExecuteRotorManoeuvreAction, ExecuteRotorManoeuvreGoal,
                                  ExecuteRotorManoeuvreResult)


def main():
    rospy.init_node('rotor_execute')
    u, v, psi = (float(x) for x in str(rospy.get_param('~target', '0.05,0.03,0.4')).split(','))
    goal = ExecuteRotorManoeuvreGoal(k=rospy.get_param('~k', 2.5),
                                     steps=rospy.get_param('~steps', 2), u_a=u, v_a=v, psi=psi,
                                     max_radius=rospy.get_param('~max_radius', 0.0),
                                     heading_turns=0, plan_index=rospy.get_param('~index', 0))
    client = actionlib.SimpleActionClient('rotor_planner/execute_manoeuvre',
                                          ExecuteRotorManoeuvreAction)
    client.wait_for_server()
    last_log = [0.0]

    def on_feedback(feedback):
        if rospy.get_time() - last_log[0] >= 1.0:
            last_log[0] = rospy.get_time()
            rospy.loginfo('rotor_execute: %s, %.0f %%, %.4f m and %.4f rad off the goal',
                          feedback.state, 100.0 * feedback.progress, feedback.distance,
                          feedback.heading_error)

    client.send_goal(goal, feedback_cb=on_feedback)
    client.wait_for_result()
    result = client.get_result()
    if result is None:
        rospy.logerr('rotor_execute: no result (%s)', client.get_goal_status_text())
        return 1
    executed = result.status == ExecuteRotorManoeuvreResult.EXECUTED
    (rospy.loginfo if executed else rospy.logerr)('rotor_execute: %s', result.message)
    return 0 if executed else 1


if __name__ == '__main__':
    sys.exit(main())
