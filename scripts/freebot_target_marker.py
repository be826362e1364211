#!/usr/bin/env python3
"""An interactive marker (Debian's python3-interactive-markers) to drag a FreeBOT chain's target
in rviz: six rings and arrows in the chain's base frame; releasing the mouse sends the pose as a
goal of freebot_ik's move_freebot action (a newer goal preempts the one in force), which
freebot_ik solves and drives to; its result is logged. The marker's server is
`freebot_target` in the node's namespace (rviz: InteractiveMarkers, update topic
freebot_target/update). It starts on ~initial ([x, y, z, qw, qx, qy, qz], Table II's A) and
follows the goals freebot_ik takes from any client (ik_target).

Private params: ~initial, ~scale [m] (0.06), ~position_only (false: full pose goals), ~frame (the
chain's fixed base, <frame_prefix>link0, in which freebot_ik takes goals; default link0).
"""
import actionlib
import rospy
from geometry_msgs.msg import PoseStamped, Quaternion
from interactive_markers.interactive_marker_server import InteractiveMarkerServer
from visualization_msgs.msg import InteractiveMarker, InteractiveMarkerControl, \
    InteractiveMarkerFeedback, Marker

from spherical_robots.msg import MoveFreebotAction, MoveFreebotGoal


def axis_controls(marker):
    for name, (w, x, y, z) in (('x', (1, 1, 0, 0)), ('z', (1, 0, 1, 0)), ('y', (1, 0, 0, 1))):
        for mode, prefix in ((InteractiveMarkerControl.ROTATE_AXIS, 'rotate_'),
                             (InteractiveMarkerControl.MOVE_AXIS, 'move_')):
            control = InteractiveMarkerControl()
            control.orientation.w, control.orientation.x = w, x
            control.orientation.y, control.orientation.z = y, z
            control.name = prefix + name
            control.interaction_mode = mode
            marker.controls.append(control)


def main():
    rospy.init_node('freebot_target')
    initial = rospy.get_param('~initial', [0.0036, 0.1636, 0.0924, 0.8610, 0.4687, 0.1356, 0.1437])
    scale = float(rospy.get_param('~scale', 0.06))
    position_only = bool(rospy.get_param('~position_only', False))
    frame = rospy.get_param('~frame', 'link0')
    client = actionlib.SimpleActionClient('move_freebot', MoveFreebotAction)
    server = InteractiveMarkerServer(rospy.get_name().split('/')[-1])

    marker = InteractiveMarker()
    marker.header.frame_id = frame
    marker.name = 'target'
    marker.description = 'FreeBOT target (release to send)'
    marker.scale = scale
    p, o = marker.pose.position, marker.pose.orientation
    p.x, p.y, p.z = initial[:3]
    o.w, o.x, o.y, o.z = initial[3:7]
    body = InteractiveMarkerControl()
    body.always_visible = True
    sphere = Marker(type=Marker.SPHERE)
    sphere.scale.x = sphere.scale.y = sphere.scale.z = 0.2 * scale
    sphere.color.r, sphere.color.g, sphere.color.a = 1.0, 0.3, 0.9
    body.markers.append(sphere)
    marker.controls.append(body)
    axis_controls(marker)

    def on_feedback(feedback):
        if feedback.event_type != InteractiveMarkerFeedback.MOUSE_UP:
            return
        goal = MoveFreebotGoal()
        goal.target.header.frame_id = frame
        goal.target.header.stamp = rospy.Time.now()
        goal.target.pose = feedback.pose
        if position_only:
            goal.target.pose.orientation = Quaternion(0.0, 0.0, 0.0, 0.0)  # all zero: position only
        client.send_goal(goal, done_cb=on_result)
        rospy.loginfo('target sent: %s', feedback.pose.position)

    def on_result(_state, result):
        if result is not None:
            rospy.loginfo('target: %s', result.message)

    def on_target(msg):  # goals from elsewhere move the marker too
        o = msg.pose.orientation
        if o.w == o.x == o.y == o.z == 0.0:  # a position-only goal: keep the marker's orientation
            msg.pose.orientation = server.get('target').pose.orientation
        server.setPose('target', msg.pose)
        server.applyChanges()

    server.insert(marker, on_feedback)
    server.applyChanges()
    rospy.Subscriber('ik_target', PoseStamped, on_target)
    rospy.spin()


if __name__ == '__main__':
    main()
