#!/usr/bin/env python3
"""Plans and executes one manoeuvre of the two-rotor sphere (launch/rotor_stack.launch).

Calls rotor_planner/plan with ~k, ~steps, ~target ("u,v,psi": metres, metres, rad) and
~max_radius [m] (0: the planner's), then publishes ~index (0 = the shortest plan) on
rotor_planner/execute once the planner subscribes. Exits 0 once it asked, 1 when there is no plan
(the planner's reason is logged). The stack does the rest (rotor_planner node).
"""
import sys

import rospy
from std_msgs.msg import UInt32

from spherical_robots.srv import PlanRotorMotion, PlanRotorMotionRequest


def main():
    rospy.init_node('rotor_execute')
    u, v, psi = (float(x) for x in str(rospy.get_param('~target', '0.05,0.03,0.4')).split(','))
    request = PlanRotorMotionRequest(k=rospy.get_param('~k', 2.5),
                                     steps=rospy.get_param('~steps', 2), u_a=u, v_a=v, psi=psi,
                                     max_radius=rospy.get_param('~max_radius', 0.0),
                                     heading_turns=0)
    rospy.wait_for_service('rotor_planner/plan')
    response = rospy.ServiceProxy('rotor_planner/plan', PlanRotorMotion)(request)
    if not response.success:
        rospy.logerr('rotor_execute: no plan: %s', response.reason)
        return 1
    index = rospy.get_param('~index', 0)
    rospy.loginfo('rotor_execute: %d plan(s); executing %d (a %.4f m, b %.4f m, gamma %.4f rad)',
                  len(response.a), index, response.a[index], response.b[index],
                  response.gamma[index])
    publisher = rospy.Publisher('rotor_planner/execute', UInt32, queue_size=1, latch=True)
    while publisher.get_num_connections() == 0 and not rospy.is_shutdown():
        rospy.sleep(0.05)
    publisher.publish(UInt32(index))
    rospy.sleep(1.0)  # latched: let the planner read it before this node goes
    return 0


if __name__ == '__main__':
    sys.exit(main())
