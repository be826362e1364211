#!/usr/bin/env python3
"""rostest of the analyzer YAMLs (config/diagnostics/*.yaml, test/diagnostics_stacks.test): every
stack runs on one master in its own namespace, each with its own aggregator. For each stack
(~stacks: {namespace: [group, ...]}), once every node has reported: the real aggregator loaded
the stack's YAML (its groups are on <ns>/diagnostics_agg), every status a node of the stack
publishes on /diagnostics (a name under <ns>/) appears in one of them, none is left to
"Other", every status the YAML expects is published, and no status of another stack is in
them (no clash between stacks).
"""
import functools
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray

import spherical_robots_testing as testing

PKG = 'spherical_robots'
NAME = 'diagnostics_coverage_check'
WALL_DEADLINE = 180.0  # [s] wall: five stacks start on two busy cores
REPORTS = 5            # /diagnostics arrays a node sends before all its statuses count as seen

wait_until = functools.partial(testing.wait_until, timeout=WALL_DEADLINE)


class DiagnosticsCoverageCheck(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node(NAME)
        cls.stacks = rospy.get_param('~stacks')
        cls.raw = testing.Recorder('/diagnostics', DiagnosticArray)
        cls.aggregated = {ns: testing.Recorder('/%s/diagnostics_agg' % ns, DiagnosticArray)
                          for ns in cls.stacks}

    def published(self, ns):
        """{node: (arrays seen, {status names})} of the stack's nodes."""
        nodes = {}
        for msg in self.raw.since(0):
            names = [s.name for s in msg.status if s.name.startswith(ns + '/')]
            if not names:
                continue
            node = names[0].split(':')[0]
            count, seen = nodes.get(node, (0, set()))
            nodes[node] = (count + 1, seen | set(names))
        return nodes

    @staticmethod
    def grouped(msg):
        """{group: [item names]} of an aggregated array: items are /<group>/<status name>, with
        the status name's '/' turned into ' ' by the aggregator."""
        groups = {}
        for status in msg.status:
            parts = status.name.split('/', 2)
            if len(parts) == 2:
                groups.setdefault(parts[1], [])
            elif len(parts) == 3:
                groups.setdefault(parts[1], []).append(parts[2])
        return groups

    def test_every_status_in_a_group(self):
        for ns, groups in self.stacks.items():
            wait_until(lambda: self.aggregated[ns].last() is not None and
                       set(groups) <= set(self.grouped(self.aggregated[ns].last())),
                       'the groups %s on /%s/diagnostics_agg' % (groups, ns))
            wait_until(lambda: all(count >= REPORTS
                                   for count, _ in self.published(ns).values()) and
                       len(self.published(ns)) >= len(groups),
                       '%d reports of every node in /%s' % (REPORTS, ns))
            # An aggregated array from after the nodes' reports counted above.
            index = self.aggregated[ns].count()
            wait_until(lambda: self.aggregated[ns].count() > index + 1,
                       'a further array on /%s/diagnostics_agg' % ns)
            grouped = self.grouped(self.aggregated[ns].last())
            self.assertNotIn('Other', grouped, '/%s: statuses in no group' % ns)
            items = [name for group in groups for name in grouped[group]]
            for node, (_, names) in self.published(ns).items():
                for name in names:
                    self.assertIn(name.replace('/', ' '), items,
                                  '/%s: %r in none of the groups %s: %s'
                                  % (ns, name, groups, grouped))
            # An expected status no node publishes (a renamed task or topic) shows "Missing".
            published = {name.replace('/', ' ') for _, names in self.published(ns).values()
                         for name in names}
            self.assertEqual(sorted(set(items) - published), [],
                             '/%s: expected by config/diagnostics but not published' % ns)
            foreign = [item for item in items if not item.startswith(ns + ' ')]
            self.assertEqual(foreign, [], '/%s: statuses of other stacks' % ns)
            rospy.loginfo('/%s: %d statuses in %s', ns,
                          sum(len(n) for _, n in self.published(ns).values()), sorted(grouped))


if __name__ == '__main__':
    rostest.rosrun(PKG, NAME, DiagnosticsCoverageCheck)
