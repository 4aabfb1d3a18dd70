#!/usr/bin/python3
"""paper.py's figures from hand-made results (no simulator): sampled figures carry their 95%
intervals as error bars, exact ones none, and --target-error reaches every frame's settings.
Standard library and Debian's python3-matplotlib only."""
import argparse
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import paper  # noqa: E402
import sweep  # noqa: E402


def result(design, scene, size, l2, stream=None, half_width=None, dram_nj=5e6):
    """A frame as sweep.collect returns it: its parameters and a stats.json tree, with
    `half_width` (a share of each figure) as sampled timing's intervals, or none (LT)."""
    key = "memory.l2.size_bytes" if design == "trax" else "memory.stream.size_bytes"
    stats = {"memory": {"l2": {"accesses": l2}}, "energy_nj": {"l2_and_stream": 2e6, "dram": dram_nj},
             "frame": {"frames_per_second": 100.0}}
    if stream is not None:
        stats["memory"]["stream"] = {"accesses": stream}
    if half_width is not None:
        stats["intervals"] = {"stats": {
            "memory": {"l2": {"accesses": {"half_width": half_width * l2}}},
            "energy_nj": {"l2_and_stream": {"half_width": half_width * 2e6}, "dram": {"half_width": half_width * dram_nj}},
        }}
        if stream is not None:
            stats["intervals"]["stats"]["memory"]["stream"] = {"accesses": {"half_width": half_width * stream}}
    params = {"config": f"sim/configs/{paper.DESIGNS[design]}.json", "scene": scene, "res": "64x64",
              "set": {key: size}}
    return sweep.Result(params, "/nowhere", stats)


def args(mode, target=None):
    return argparse.Namespace(scenes=["sibenik"], res="64x64", mode=mode, target_error=target, target_stats=None)


class ErrorBars(unittest.TestCase):
    def test_the_half_width_is_read_from_the_intervals_tree(self):
        r = result("trax", "sibenik", 1 << 20, 1000.0, half_width=0.1)
        self.assertAlmostEqual(paper.err(r, "memory.l2.accesses"), 100.0)
        self.assertAlmostEqual(paper.err(r, "energy_nj.dram", 1e-6), 0.5)
        self.assertEqual(paper.err(r, "frame.frames_per_second"), 0.0)  # not in the tree: exact
        self.assertEqual(paper.err(result("trax", "sibenik", 1 << 20, 1000.0), "memory.l2.accesses"), 0.0)

    def draw(self, runs, a):
        """The Fig. 4 axes as paper.plot_fig4 draws them; the PNG is written too."""
        plt = paper.pyplot()
        with tempfile.TemporaryDirectory() as d:
            png = os.path.join(d, "fig4.png")
            paper.plot_fig4(runs, a, png)
            self.assertGreater(os.path.getsize(png), 1000)
        fig = plt.gcf()
        ax = fig.axes[0]
        plt.close(fig)
        return ax

    def test_sampled_figures_are_drawn_with_error_bars(self):
        runs = [result("trax", "sibenik", z, 1000.0 * i + 500, half_width=0.1) for i, z in enumerate(paper.SIZES)]
        runs += [result("streams", "sibenik", z, 800.0, 300.0, half_width=0.2) for z in paper.SIZES]
        ax = self.draw(runs, args("sampled", 0.02))
        bars = [c for c in ax.containers if type(c).__name__ == "ErrorbarContainer"]
        self.assertEqual(len(bars), 3)  # trax L2, streams L2, streams stream accesses
        self.assertIn("target \u00b12%", ax.figure._suptitle.get_text())
        # The first trax point's bar spans its estimate +- 10%.
        trax = next(c for c in bars if "trax" in c.get_label())
        segments = trax.lines[2][0].get_segments()
        (x0, y0), (x1, y1) = segments[0]
        self.assertAlmostEqual(y0, 450.0)
        self.assertAlmostEqual(y1, 550.0)

    def test_exact_figures_have_no_error_bars(self):
        runs = [result("trax", "sibenik", z, 1000.0) for z in paper.SIZES]
        ax = self.draw(runs, args("lt"))
        self.assertEqual([c for c in ax.containers if type(c).__name__ == "ErrorbarContainer"], [])
        self.assertEqual(len(ax.lines), 1)


class TargetError(unittest.TestCase):
    def test_the_target_reaches_every_frame_of_a_spec(self):
        a = argparse.Namespace(scenes=["sibenik"], res="128x128", mode="sampled", target_error=0.02,
                               target_stats=["frame.cycles", "memory.l2.accesses"])
        frames = paper.from_spec("equal-sram", a)
        self.assertTrue(frames)
        for p in frames:
            self.assertEqual(p["set"]["timing.sample_target_error"], 0.02)
            self.assertEqual(p["set"]["timing.sample_target_stats"], "frame.cycles,memory.l2.accesses")
        a.target_stats = None
        a.target_error = None
        self.assertTrue(all("timing.sample_target_error" not in p["set"] for p in paper.from_spec("equal-sram", a)))


if __name__ == "__main__":
    unittest.main()
