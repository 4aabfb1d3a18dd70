#!/usr/bin/python3
"""interval_coverage.py compares a loosely-timed frame with its sampled twin only when both ran
the same kernel image: the pairing, on rows as the sweep writes them."""
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import interval_coverage  # noqa: E402


def row(kernel):
    return {"status": "done", "kernel": kernel, "frame.cycles [cycles]": 1.0}


class SameKernelPairs(unittest.TestCase):
    def test_pairs_only_frames_run_under_the_same_kernel(self):
        lt = {("trax", "a", "8x8", 1): row("baseline.elf 01"), ("streams", "a", "8x8", 1): row("streams.elf 02"),
              ("streams", "b", "8x8", 1): row(""), ("trax", "c", "8x8", 1): row("baseline.elf 01")}
        sampled = {("trax", "a", "8x8", 1): row("baseline.elf 01"), ("streams", "a", "8x8", 1): row("streams.elf 03"),
                   ("streams", "b", "8x8", 1): row("streams.elf 03")}
        pairs, mismatched, unchecked = interval_coverage.same_kernel_pairs(lt, sampled)
        self.assertEqual(pairs, [("streams", "b", "8x8", 1), ("trax", "a", "8x8", 1)])
        self.assertEqual(mismatched, [(("streams", "a", "8x8", 1), ("streams.elf 02", "streams.elf 03"))])
        self.assertEqual(unchecked, [("streams", "b", "8x8", 1)])


if __name__ == "__main__":
    unittest.main()
