#!/usr/bin/env python3
"""Offers a bag's latched messages to late subscribers and re-sends them after every jump back in
simulated time (launch/replay.launch).

    replay_latched.py BAG [--delay 0.5] [--exclude TOPIC ...] [--topics TOPIC ...]

A stack publishes some topics once, latched (the controller's desired_path, the plant's
terrain_marker, /tf_static). When `rosbag play` loops, or the bag is played again, /clock jumps
back to the bag's start and rviz resets every display (VisualizationManager::resetTime) on its next
frame, while rosbag re-publishes those messages at the same moment: a message that rviz receives
before it notices the jump is cleared by the reset and never comes again (the desired path vanished
in about one loop of three). This node reads the last message of every latched connection from the
bag, offers it on the same topic (latched), and publishes it again --delay seconds of wall time
after each jump back, by which time rviz has reset.

/tf_static is merged into one message, as tf2_ros's StaticTransformBroadcaster does: the bag holds
one message per static broadcaster of the stack (the plant's map -> <ns>/odom, the URDF's fixed
joints), but `rosbag play` is one node, and roscpp latches only the last message a node published
on a topic, so an rviz that subscribes after the bag's first second got only one of them (the
replay screenshot test saw no map frame at all, every display in error, on a busy machine).
"""
import argparse
import sys
import threading

import rosbag
import rospy
from rosgraph_msgs.msg import Clock
from tf2_msgs.msg import TFMessage

STATIC_TF = '/tf_static'


def latched_messages(bag_path, exclude, only=None):
    """{topic: [message, ...]}: the last message of each latched connection in the bag (of the
    topics in `only`, if given), except the topics in `exclude`; /tf_static as one TFMessage with
    the last transform to each child frame."""

    def is_latched(topic, datatype, md5sum, msg_def, header):
        return (header.get('latching') in ('1', b'1') and topic not in exclude
                and (not only or topic in only))

    last = {}
    static = {}
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, _, header in bag.read_messages(connection_filter=is_latched,
                                                       return_connection_header=True):
            if topic == STATIC_TF:
                static.update((t.child_frame_id, t) for t in msg.transforms)
            else:
                last[(topic, header.get('callerid'))] = msg
    by_topic = {}
    for (topic, _), msg in sorted(last.items(), key=lambda item: item[0][0]):
        by_topic.setdefault(topic, []).append(msg)
    if static:
        by_topic[STATIC_TF] = [TFMessage(transforms=[static[c] for c in sorted(static)])]
    return by_topic


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('bag')
    parser.add_argument('--delay', type=float, default=0.5, help='[s] wall time after a jump')
    parser.add_argument('--exclude', nargs='*', default=[])
    parser.add_argument('--topics', nargs='*', default=[],
                        help='only these topics (as rosbag play --topics)')
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node('replay_latched')
    messages = latched_messages(args.bag, set(args.exclude), set(args.topics))
    publishers = {topic: rospy.Publisher(topic, type(msgs[0]), queue_size=len(msgs), latch=True)
                  for topic, msgs in messages.items()}
    rospy.loginfo('replay_latched: offers %s, and re-sends them after each jump back in time',
                  ', '.join(sorted(publishers)) or 'nothing (no latched topics in the bag)')
    lock = threading.Lock()
    state = {'last': None}

    def resend():
        for topic, msgs in messages.items():
            for msg in msgs:
                publishers[topic].publish(msg)
        rospy.loginfo('replay_latched: sent %d latched topics', len(messages))

    def on_clock(msg):
        t = msg.clock.to_sec()
        with lock:
            jumped = state['last'] is not None and t < state['last']
            state['last'] = t
        if jumped and messages:
            timer = threading.Timer(args.delay, resend)
            timer.daemon = True
            timer.start()

    resend()  # latched: what a subscriber gets whenever it comes
    rospy.Subscriber('/clock', Clock, on_clock, queue_size=100)
    rospy.spin()
    return 0


if __name__ == '__main__':
    sys.exit(main())
