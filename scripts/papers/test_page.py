"""Tests of the page's numbers and of the trace measures, on made-up runs:
    python3 -m unittest discover -s scripts/papers -t scripts -p 'test_*.py'
"""

import math
import unittest

from papers import measures, page
from papers.rows import EXACT, Row, Section
from papers.runs import MeasurementError


class FakeRun:
    """A run from a dict of metrics and a dict of trace columns."""

    def __init__(self, metrics=None, columns=None, settings=None, seed=1):
        self.step, self.seed = "x:a", seed
        self._metrics, self._columns, self._settings = metrics or {}, columns or {}, settings or {}

    def where(self):
        return f"{self.step} seed {self.seed}"

    def metric(self, name):
        if name not in self._metrics:
            raise MeasurementError(f"no metric '{name}'")
        return self._metrics[name]

    def column(self, name):
        return self._columns[name]

    def setting(self, *path):
        return self._settings[path]

    def interval(self, name):
        return tuple(self._metrics[name])


SECTION = Section("demo", (
    Row("x:a", "error (m)", "error", "the paper's claim"),
    Row("x:a", "time (s)", lambda run: run.metric("time") if run.metric("time") >= 0 else None),
    Row("x:a", "seeds lost", lambda run: run.metric("error") > 1.0, tolerance=EXACT,
        counts=True),
))


def measured(errors, times=(1.0, 2.0, 3.0)):
    runs = {("x:a", "", seed): FakeRun({"error": e, "time": t}, seed=seed)
            for seed, e, t in zip((1, 2, 3), errors, times)}
    return page.measure_section(SECTION, runs, [1, 2, 3])


def written_page(values):
    text = "intro\n" + page.begin_marker("demo", [1, 3]) + "\n" + page.end_marker("demo") + "\nend"
    return page.replace_block(text, "demo", [1, 2, 3], page.table(SECTION, values, [1, 2, 3]))


def failures_of(text, values):
    return page.compare("p.md", SECTION, page.stated_rows(text, "demo"), values)


class Numbers(unittest.TestCase):
    def test_cells_read_back_as_written(self):
        for numbers in ((0.0158, 0.0151, 0.0169), (2.95e7, 2e7, 4.19e7), (1.0, 1.0, 1.0),
                        (-1.5, -2.25, 3e-5)):
            cell = page.Measured(numbers, 10, 10).cell(False)
            parsed, _, _ = page.parse_cell(cell)
            for stated, true in zip(parsed, numbers):
                self.assertLessEqual(abs(stated - true), 0.005 * abs(true), cell)
        self.assertEqual(page.parse_cell("7 of 10 seeds"), ((7.0,), 10, 10))
        self.assertEqual(page.parse_cell("0.3 [0.3, 0.3] on 4 of 10 seeds"),
                         ((0.3, 0.3, 0.3), 4, 10))
        self.assertEqual(page.parse_cell("never (0 of 10 seeds)"), ((), 0, 10))
        self.assertEqual(page.parse_cell("median 2.9 [1.1, 39]"), ((2.9, 1.1, 39.0), None, None))
        self.assertIsNone(page.parse_cell("about 3"))

    def test_tolerances(self):
        self.assertTrue(page.within(1.0, 1.1, "±10 %"))
        self.assertFalse(page.within(1.0, 1.11, "±10 %"))
        self.assertFalse(page.within(-1.0, -0.89, "±10 %"))
        self.assertTrue(page.within(2.0, 2.5, "±0.5"))
        self.assertFalse(page.within(2.0, 2.51, "±0.5"))
        self.assertTrue(page.within(9.0, 9.0, "exact"))
        self.assertFalse(page.within(9.0, 8.0, "exact"))
        self.assertTrue(page.within(3.0, 30.0, "not checked (a timing)"))
        with self.assertRaises(page.PageError):
            page.within(1.0, 1.0, "roughly")


class Check(unittest.TestCase):
    def test_measures_mean_range_and_counts(self):
        values = measured((0.5, 2.0, 3.5), times=(1.0, -1.0, 4.0))
        self.assertEqual(values[("x:a", "error (m)")].numbers, (2.0, 0.5, 3.5))
        self.assertEqual(values[("x:a", "time (s)")].numbers, (2.5, 1.0, 4.0))
        self.assertEqual(values[("x:a", "time (s)")].defined, 2)
        self.assertEqual(values[("x:a", "seeds lost")].numbers, (2.0,))
        median_row = Row("x:a", "median error (m)", "error", median=True)
        runs = {("x:a", "", seed): FakeRun({"error": e}) for seed, e in ((1, 0.5), (2, 2.0),
                                                                          (3, 30.0))}
        self.assertEqual(page.measure(median_row, runs, [1, 2, 3]).numbers, (2.0, 0.5, 30.0))

    def test_a_written_page_passes_and_keeps_the_text_around(self):
        values = measured((0.5, 2.0, 3.5))
        text = written_page(values)
        self.assertTrue(text.startswith("intro\n") and text.endswith("\nend"))
        self.assertEqual(failures_of(text, values), [])
        self.assertEqual(page.page_seeds(text, [SECTION]), [1, 2, 3])

    def test_a_number_outside_its_tolerance_fails_naming_it(self):
        text = written_page(measured((0.5, 2.0, 3.5)))
        self.assertEqual(failures_of(text, measured((0.5, 2.0, 3.8))), [])  # max within 10 %
        failures = failures_of(text, measured((0.5, 2.0, 4.0)))
        self.assertEqual(len(failures), 1, failures)
        self.assertIn("x:a 'error (m)', max: the page states 3.5, measured 4", failures[0])
        self.assertIn("tolerance ±10 %", failures[0])
        failures = failures_of(text, measured((0.5, 0.9, 3.5)))  # one seed fewer lost
        self.assertTrue(any("'seeds lost', count: the page states 2, measured 1" in f
                            for f in failures), failures)

    def test_a_measure_defined_on_fewer_seeds_fails(self):
        text = written_page(measured((0.5, 2.0, 3.5)))
        failures = failures_of(text, measured((0.5, 2.0, 3.5), times=(1.0, 2.0, -1.0)))
        self.assertEqual(len(failures), 1, failures)
        self.assertIn("'time (s)': the page states it on 3 seeds, it is now defined on 2",
                      failures[0])

    def test_a_missing_or_stale_row_fails(self):
        values = measured((0.5, 2.0, 3.5))
        text = written_page(values)
        without = "\n".join(line for line in text.split("\n") if "time (s)" not in line)
        self.assertIn("no row for x:a 'time (s)'", " ".join(failures_of(without, values)))
        renamed = text.replace("| error (m) |", "| error (cm) |")
        self.assertIn("no longer measures", " ".join(failures_of(renamed, values)))

    def test_markers_are_required(self):
        with self.assertRaises(page.PageError):
            page.stated_rows("no markers here", "demo")


class TraceMeasures(unittest.TestCase):
    def test_integration_follows_a_true_arc(self):
        # Truth: a constant v, ω arc, exact; the speeds given are the true ones, so the
        # integrated path (eq. 13) must stay on the arc up to its midpoint-rule error.
        v, w, period, steps, base = 0.1, 0.4, 0.05, 400, 0.12
        t = [k * period for k in range(steps)]
        x = [(v / w) * math.sin(w * s) for s in t]
        y = [(v / w) * (1 - math.cos(w * s)) for s in t]
        theta = [w * s for s in t]
        right, left = v + w * base / 2, v - w * base / 2
        columns = {"t": t, "x_true": x, "y_true": y, "x_odo": x, "y_odo": y, "th_odo": theta,
                   "v_enc": [v] * steps, "w_enc": [w] * steps,
                   "wheel_kf_right": [None] + [right] * (steps - 1),
                   "wheel_kf_left": [None] + [left] * (steps - 1)}
        run = FakeRun(columns=columns, settings={("robot", "wheel_base"): base})
        self.assertLess(measures.wheel_kf_position_rms(run), 1e-5)
        # 1 % too fast on the right wheel: the path bends away, the error is no longer small.
        columns["wheel_kf_right"] = [None] + [1.01 * right] * (steps - 1)
        self.assertGreater(measures.wheel_kf_position_rms(run), 0.01)

    def test_the_clis_integrated_position_is_used_only_where_it_agrees_with_the_script(self):
        steps, period, v = 200, 0.05, 0.1
        t = [k * period for k in range(steps)]
        x = [v * s for s in t]
        zeros = [0.0] * steps
        columns = {"t": t, "x_true": x, "y_true": zeros, "x_odo": x, "y_odo": zeros,
                   "th_odo": zeros, "v_enc": [v] * steps, "w_enc": zeros,
                   "v_kf": [None] + [1.02 * v] * (steps - 1), "w_kf": [None] + zeros[1:]}
        own = measures.velocity_kf_position_rms(FakeRun(columns=columns))
        self.assertGreater(own, 0.01)  # 2 % too fast over 10 m: decimetres
        ratio = measures.velocity_kf_position("velocity_kf_position_to_odometry_ratio")
        agreeing = FakeRun({"rms_velocity_kf_position_error_m": 1.0005 * own,
                            "velocity_kf_position_to_odometry_ratio": 7.0}, columns)
        self.assertEqual(ratio(agreeing), 7.0)
        disagreeing = FakeRun({"rms_velocity_kf_position_error_m": 1.002 * own,
                               "velocity_kf_position_to_odometry_ratio": 7.0}, columns)
        with self.assertRaises(MeasurementError):
            ratio(disagreeing)

    def test_first_wall_contact(self):
        columns = {"t": [10.0, 10.5, 11.0, 11.5], "touching_wall": [0.0, 0.0, 1.0, 1.0],
                   "x_est": [0.0, 0.0, 0.3, 0.0], "y_est": [0.0, 0.0, 0.4, 0.0],
                   "x_true": [0.0] * 4, "y_true": [0.0] * 4}
        run = FakeRun(columns=columns)
        self.assertEqual(measures.first_wall_contact_time(run), 1.0)
        self.assertAlmostEqual(measures.position_error_at_first_contact(run), 0.5)
        columns["touching_wall"] = [0.0] * 4
        self.assertIsNone(measures.first_wall_contact_time(run))
        self.assertIsNone(measures.position_error_at_first_contact(run))

    def test_mean_nees_against_its_time_average_bounds(self):
        def inside(mean):
            run = FakeRun({"mean_nees": mean, "time_average_nees_99_9_bounds": [2.5, 3.5]})
            return measures.mean_nees_within_time_average_bounds(run)
        self.assertTrue(inside(3.2))
        self.assertFalse(inside(3.6))
        self.assertFalse(inside(0.12))

    def test_integration_refuses_a_trace_whose_odometry_it_cannot_reproduce(self):
        steps = 10
        columns = {"t": [0.05 * k for k in range(steps)], "x_odo": [0.0] * steps,
                   "y_odo": [0.0] * steps, "th_odo": [0.0] * steps,
                   "v_enc": [0.1] * steps, "w_enc": [0.0] * steps}
        with self.assertRaises(MeasurementError):
            measures.velocity_kf_position_rms(FakeRun(columns=columns))

    def test_time_after_the_displacement(self):
        t = [0.5 * k for k in range(10)]
        errors = [0.0, 0.0, 1.0, 1.0, 0.5, 0.2, 0.05, 0.01, 0.3, 0.01]
        columns = {"t": t, "x_est": errors, "y_est": [0.0] * 10, "x_true": [0.0] * 10,
                   "y_true": [0.0] * 10}
        run = FakeRun(columns=columns, settings={("displacement", "time"): 0.5})
        self.assertEqual(measures.time_to_position_within(0.1)(run), 2.5)  # t = 3.0
        self.assertIsNone(measures.time_to_position_within(0.001)(run))


if __name__ == "__main__":
    unittest.main()
