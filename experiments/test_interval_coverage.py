#!/usr/bin/python3
"""interval_coverage.py compares a loosely-timed frame with its sampled twin only when both ran
the same kernel image (the pairing, on rows as the sweep writes them), with the clock's
systematic error in the frame time's interval."""
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


class FrameTimeHalfWidth(unittest.TestCase):
    """The frame time's half-width holds the clock's systematic error: as the run reported it, or
    recomputed for a run that published both frame times but not the term."""

    def test_a_run_with_the_term_is_taken_as_it_is(self):
        r = {"frame.cycles [cycles]": 1000.0, "intervals.stats.frame.cycles.half_width [cycles]": 40.0,
             "intervals.frame_time_systematic [ratio]": 0.025}
        self.assertEqual(interval_coverage.frame_time_half_width(r), (40.0, "in run"))

    def test_an_older_run_adds_the_larger_of_the_disagreement_and_the_bound(self):
        base = {"frame.cycles [cycles]": 1000.0, "intervals.stats.frame.cycles.half_width [cycles]": 4.0,
                "intervals.simulated_frame_cycles [cycles]": 1000.0}
        close = dict(base, **{"intervals.samples_frame_cycles [cycles]": 1010.0})
        far = dict(base, **{"intervals.samples_frame_cycles [cycles]": 1100.0})
        self.assertEqual(interval_coverage.frame_time_half_width(close), (4.0 + 25.0, "recomputed"))
        self.assertEqual(interval_coverage.frame_time_half_width(far), (4.0 + 100.0, "recomputed"))

    def test_a_run_without_both_frame_times_keeps_its_spread(self):
        r = {"frame.cycles [cycles]": 1000.0, "intervals.stats.frame.cycles.half_width [cycles]": 4.0}
        self.assertEqual(interval_coverage.frame_time_half_width(r), (4.0, "none"))


if __name__ == "__main__":
    unittest.main()
