#!/usr/bin/env python3
"""low_latency:=true (scripts/hold_cpu_latency.py): while the stack runs, the kernel's CPU
wake-up latency limit, read back from /dev/cpu_dma_latency, is 0 us (with no request it is
2,000,000,000 us), and the stack runs. Skipped unless this process may read the file (root)."""
import os
import struct
import sys
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry
from spherical_robots_testing import wait_until

REQUEST_FILE = '/dev/cpu_dma_latency'


def latency_limit():
    """[us] the current limit: the least of every open request (opening it adds none)."""
    with open(REQUEST_FILE, 'rb') as limit:
        return struct.unpack('i', limit.read(4))[0]


class LowLatencyCheck(unittest.TestCase):
    def test_latency_held_at_zero_while_the_stack_runs(self):
        if not os.access(REQUEST_FILE, os.R_OK | os.W_OK):
            self.skipTest('%s needs root' % REQUEST_FILE)
        odometry = []
        rospy.Subscriber('odom', Odometry, odometry.append, queue_size=100)
        wait_until(lambda: len(odometry) > 10, 'the stack to publish odom', 60.0)
        try:
            wait_until(lambda: latency_limit() == 0, 'the CPU wake-up latency limit at 0 us', 20.0)
        except AssertionError as error:
            raise AssertionError('%s; it is %d us' % (error, latency_limit()))


if __name__ == '__main__':
    rospy.init_node('low_latency_check')
    rostest.rosrun('spherical_robots', 'low_latency_check', LowLatencyCheck, sys.argv)
