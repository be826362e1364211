#!/usr/bin/env python3
"""Holds the CPUs at their lowest wake-up latency while it runs: a Linux PM QoS request of 0 us on
/dev/cpu_dma_latency, which lasts as long as the file stays open, as real-time setups make one.
A stack in lock-step is bound by waking the next node of its loop, and an idle CPU that sleeps
takes long to wake (on a virtual machine, a halted virtual CPU the host must schedule again):
with the idle CPUs polling instead, the terrain stack as processes ran at about 100x real time
instead of 42x on a 2-core virtual machine (docs/lockstep.md, "Wake-up latency"). Polling idle
CPUs cost power, and on a shared host its CPU time, so it is the stacks' choice
(low_latency:=true), not their default. It needs write access to /dev/cpu_dma_latency (root);
without it, it logs a warning and the stack runs at the machine's own latency."""
import struct

import rospy

REQUEST_FILE = '/dev/cpu_dma_latency'


def main():
    rospy.init_node('hold_cpu_latency')
    try:
        request = open(REQUEST_FILE, 'wb', buffering=0)
        request.write(struct.pack('i', 0))  # [us], a native 32-bit integer
    except OSError as error:
        rospy.logwarn('low_latency: cannot hold %s at 0 us (%s; it needs root): the stack runs at '
                      "the machine's own wake-up latency", REQUEST_FILE, error)
        rospy.spin()
        return
    rospy.loginfo('low_latency: CPU wake-up latency held at 0 us (%s) while the stack runs',
                  REQUEST_FILE)
    with request:
        rospy.spin()


if __name__ == '__main__':
    main()
