#!/usr/bin/env python3
"""Re-sends a bag's latched messages after every jump back in simulated time (launch/replay.launch).

    replay_latched.py BAG [--delay 0.5] [--exclude /tf_static] [--topics TOPIC ...]

A stack publishes some topics once, latched (the controller's desired_path, the plant's
terrain_marker). When `rosbag play` loops, or the bag is played again, /clock jumps back to the
bag's start and rviz resets every display (VisualizationManager::resetTime) on its next frame,
while rosbag re-publishes those messages at the same moment: a message that rviz receives before
it notices the jump is cleared by the reset and never comes again (the desired path vanished in
about one loop of three). This node reads the last message of every latched connection from the
bag, offers it on the same topic (latched), and publishes it again --delay seconds of wall time
after each jump back, by which time rviz has reset. /tf_static is left out by default: tf2 keeps
static transforms when a buffer is cleared.
"""
import argparse
import sys
import threading

import rosbag
import rospy
from rosgraph_msgs.msg import Clock


def latched_messages(bag_path, exclude, only=None):
    """{topic: [message, ...]}: the last message of each latched connection in the bag (of the
    topics in `only`, if given), except the topics in `exclude`."""

    def is_latched(topic, datatype, md5sum, msg_def, header):
        return (header.get('latching') in ('1', b'1') and topic not in exclude
                and (not only or topic in only))

    last = {}
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, _, header in bag.read_messages(connection_filter=is_latched,
                                                       return_connection_header=True):
            last[(topic, header.get('callerid'))] = msg
    by_topic = {}
    for (topic, _), msg in sorted(last.items(), key=lambda item: item[0][0]):
        by_topic.setdefault(topic, []).append(msg)
    return by_topic


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('bag')
    parser.add_argument('--delay', type=float, default=0.5, help='[s] wall time after a jump')
    parser.add_argument('--exclude', nargs='*', default=['/tf_static'])
    parser.add_argument('--topics', nargs='*', default=[],
                        help='only these topics (as rosbag play --topics)')
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node('replay_latched')
    messages = latched_messages(args.bag, set(args.exclude), set(args.topics))
    publishers = {topic: rospy.Publisher(topic, type(msgs[0]), queue_size=len(msgs), latch=True)
                  for topic, msgs in messages.items()}
    rospy.loginfo('replay_latched: re-sends %s after each jump back in time',
                  ', '.join(sorted(publishers)) or 'nothing (no latched topics in the bag)')
    lock = threading.Lock()
    state = {'last': None}

    def resend():
        for topic, msgs in messages.items():
            for msg in msgs:
                publishers[topic].publish(msg)
        rospy.loginfo('replay_latched: re-sent %d latched topics', len(messages))

    def on_clock(msg):
        t = msg.clock.to_sec()
        with lock:
            jumped = state['last'] is not None and t < state['last']
            state['last'] = t
        if jumped and messages:
            timer = threading.Timer(args.delay, resend)
            timer.daemon = True
            timer.start()

    rospy.Subscriber('/clock', Clock, on_clock, queue_size=100)
    rospy.spin()
    return 0


if __name__ == '__main__':
    sys.exit(main())
