#!/usr/bin/env python3
"""How the terrain stack uses the CPUs, read back from the kernel while it runs.

* loop_cpu (default auto; core/loop_cpu.hpp): every thread of the lock-step loop's nodes (the
  plant, the controller, the hardware interface) may run on one and the same CPU, which the
  plant reports on /diagnostics ("lock-step CPU"); an observer (robot_state_publisher) keeps every
  CPU the stack was started with.
* low_latency:=true (scripts/hold_cpu_latency.py): the kernel's CPU wake-up latency limit, read
  back from /dev/cpu_dma_latency, is 0 us (with no request it is 2,000,000,000 us). Skipped unless
  this process may read the file (root).
"""
import os
import struct
import sys
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from nav_msgs.msg import Odometry
from spherical_robots_testing import pid_of, wait_until

REQUEST_FILE = '/dev/cpu_dma_latency'
LOOP = ['terrain_plant', 'pure_pursuit_controller', 'hardware_interface']
OBSERVER = 'robot_state_publisher'


def latency_limit():
    """[us] the current limit: the least of every open request (opening it adds none)."""
    with open(REQUEST_FILE, 'rb') as limit:
        return struct.unpack('i', limit.read(4))[0]


def cpus_of_threads(pid):
    """The set of CPUs each thread of process `pid` may run on, as the kernel has it."""
    return {tid: frozenset(os.sched_getaffinity(int(tid)))
            for tid in os.listdir('/proc/%d/task' % pid)}


class CpuUseCheck(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.odometry = []
        cls.reported_cpu = []
        rospy.Subscriber('odom', Odometry, cls.odometry.append, queue_size=100)
        rospy.Subscriber('/diagnostics', DiagnosticArray, cls.on_diagnostics, queue_size=10)
        wait_until(lambda: len(cls.odometry) > 10, 'the stack to publish odom', 60.0)

    @classmethod
    def on_diagnostics(cls, msg):
        for status in msg.status:
            if status.name.endswith(': terrain plant'):
                cls.reported_cpu += [kv.value for kv in status.values if kv.key == 'lock-step CPU']

    def test_loop_on_one_cpu_observers_free(self):
        # -1 (none) until time starts, when the plant chooses.
        wait_until(lambda: self.reported_cpu and self.reported_cpu[-1] != '-1',
                   "the plant's lock-step CPU on /diagnostics", 20.0)
        cpu = int(self.reported_cpu[-1])
        started_with = frozenset(os.sched_getaffinity(0))  # roslaunch's, which rostest passed on
        self.assertIn(cpu, started_with)
        for name in LOOP:
            pid = pid_of(rospy.resolve_name(name))
            self.assertIsNotNone(pid, name)
            # A participant moves when its first request names the CPU: by now it has had many.
            threads = cpus_of_threads(pid)
            self.assertEqual(set(threads.values()), {frozenset([cpu])},
                             '%s (pid %d): its threads may run on %s' % (name, pid, threads))
        observer = cpus_of_threads(pid_of(rospy.resolve_name(OBSERVER)))
        self.assertEqual(set(observer.values()), {started_with}, OBSERVER)

    def test_latency_held_at_zero_while_the_stack_runs(self):
        if not os.access(REQUEST_FILE, os.R_OK | os.W_OK):
            self.skipTest('%s needs root' % REQUEST_FILE)
        try:
            wait_until(lambda: latency_limit() == 0, 'the CPU wake-up latency limit at 0 us', 20.0)
        except AssertionError as error:
            raise AssertionError('%s; it is %d us' % (error, latency_limit()))


if __name__ == '__main__':
    rospy.init_node('cpu_use_check')
    rostest.rosrun('spherical_robots', 'cpu_use_check', CpuUseCheck, sys.argv)
