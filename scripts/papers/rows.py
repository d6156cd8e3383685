"""The numbers docs/papers.md states: for each paper, its results beside what its lesson
measures. A row's measure is a summary.json metric name or a function of a run
(scripts/papers/measures.py); a counting row's measure is a condition, and the table says on
how many seeds it held.

The tolerance is how far a recomputed number may move before `--check` fails: ±10 % for the
deterministic runs (the same build and seed give the same bits, so a change means the code
or the lesson changed and the page must be regenerated). Timings are shown but not checked:
they depend on the machine and on what else it runs (one run's UKF/EKF cost ratio was
anywhere from 0.2 to 19 on a loaded 2-core machine, when a pause of the process lands in
one filter's timed step); their rows state the median over the seeds, which such a pause
moves less than the mean.
"""

from dataclasses import dataclass
from typing import Callable, Union

from . import measures

DETERMINISTIC = "±10 %"
TIMING = "not checked (a timing: it depends on the machine and its load)"
EXACT = "exact"


@dataclass(frozen=True)
class Row:
    step: str
    quantity: str
    measure: Union[str, Callable]
    paper: str = ""
    tolerance: str = DETERMINISTIC
    counts: bool = False  # measure(run) → bool; the cell is "k of N seeds"
    overlay: str = ""  # TOML applied over the step's preset (legofeup-cli run -c)
    median: bool = False  # the cell's first number is the median over the seeds, not the mean


@dataclass(frozen=True)
class Section:
    key: str  # the page's markers: <!-- BEGIN generated: KEY ... -->
    rows: tuple

    def cases(self):
        """The (step, overlay) pairs its rows are measured on."""
        return {(row.step, row.overlay) for row in self.rows}

    def timed_cases(self):
        """The pairs with a row that is a timing."""
        return {(row.step, row.overlay) for row in self.rows if row.tolerance == TIMING}


def beats_encoders(measure):
    """Holds when the measured RMS position error is below the run's raw-encoder one."""
    def condition(run):
        value = run.metric(measure) if isinstance(measure, str) else measure(run)
        return value < run.metric("rms_odometry_position_error_m")
    return condition


def final_error_above(limit):
    return lambda run: run.metric("final_position_error_m") > limit


def ratio_below_one(measure):
    """Holds when the measured ratio to the raw encoders' error is below 1."""
    return lambda run: (run.metric(measure) if isinstance(measure, str) else measure(run)) < 1.0


CONTACT = "first wall contact (s from the start)"
RECOVERED = "seeds where the filter finds the robot again (error under 0.1 m for good)"
RECOVERY_TIME = "time to recover (s; the bump to the error staying under 0.1 m)"


# Appendix A's ICP settings, over the laser lesson's own.
PAPER_ICP = "[laser]\nicp_max_correspondence_distance = 0.002\nicp_max_iterations = 700\n"

LEGOFEUP = Section("legofeup", (
    Row("a", "final position error (m)", "final_position_error_m",
        "a) covariance increases without bounds; the vehicle never corrects its position "
        "and is lost rapidly"),
    Row("a", "filter's position σ, √(Pxx+Pyy), at the start (m)", measures.position_sigma(0)),
    Row("a", "filter's position σ at the end (m)", measures.position_sigma(-1)),
    Row("a", "share of steps with the robot against a wall", measures.touching_wall_fraction),
    Row("a", CONTACT, measures.first_wall_contact_time),
    Row("a", "position error at the first wall contact (m)",
        measures.position_error_at_first_contact),
    Row("b", "RMS position error (m)", "rms_position_error_m",
        "b) R very low, no IR noise: localises with success, only because the readings are "
        "ideal"),
    Row("c", "RMS position error (m)", "rms_position_error_m",
        "c) R very low, IR noise: does not localise the vehicle correctly"),
    Row("c", "mean heading change per update (rad)", "mean_update_heading_step_rad"),
    Row("c", "share of steps with the robot against a wall", measures.touching_wall_fraction),
    Row("c", CONTACT, measures.first_wall_contact_time),
    Row("d", "mean heading change per update (rad)", "mean_update_heading_step_rad",
        "d) R = injected noise, Q very low: the readings are rejected, localisation is "
        "odometry only"),
    Row("d", "RMS distance between estimate and odometry (m)", "rms_estimate_to_odometry_m"),
    Row("d", "mean NEES (consistent: 3)", "mean_nees"),
    Row("d", "share of steps with the robot against a wall", measures.touching_wall_fraction),
    Row("d", CONTACT, measures.first_wall_contact_time),
    Row("e", "mean heading change per update (rad)", "mean_update_heading_step_rad",
        "e) Q very high: \"similar to step b)\", the update trusts each wall with a "
        "confidence near 100 %"),
    Row("e", "RMS position error (m)", "rms_position_error_m"),
    Row("e", "mean NEES (consistent: 3)", "mean_nees"),
    Row("e", "share of steps with the robot against a wall", measures.touching_wall_fraction),
    Row("e", CONTACT, measures.first_wall_contact_time),
    Row("f", "RMS position error (m)", "rms_position_error_m",
        "f) the students tune Q and R to the best solution"),
    Row("f", "share of steps with NEES inside its 95 % bounds", "nees_inside_fraction"),
    Row("f", "mean NEES (consistent: 3)", "mean_nees"),
    Row("f", "seeds with the mean NEES inside its time-average 99.9 % bounds",
        measures.mean_nees_within_time_average_bounds, tolerance=EXACT, counts=True),
    Row("g", "max position error (m)", "max_position_error_m",
        "beyond the paper: its association (Fig. 4) with fixed gates, 10 cm and 20°, after a "
        "15 cm bump"),
    Row("g", "final position error (m)", "final_position_error_m"),
    Row("g", RECOVERED, "kidnap_recovered", tolerance=EXACT, counts=True),
    Row("h", "final position error (m)", "final_position_error_m",
        "beyond the paper: the same bump under a Mahalanobis gate"),
    Row("h", RECOVERED, "kidnap_recovered", tolerance=EXACT, counts=True),
    Row("h", RECOVERY_TIME, measures.time_to_recover),
))

LASER = Section("laser", (
    Row("laser:a", "odometry's final position error (m)", "final_odometry_position_error_m",
        "one rectangular lap: odometry ends about 15 cm from the starting point"),
    Row("laser:a", "odometry's end to start (m)", "odometry_end_to_start_m"),
    Row("laser:a", "filter's final position error (m)", "final_position_error_m",
        "the EKF ends about 2.5 cm from the actual starting position"),
    Row("laser:a", "estimate's end to start (m)", "estimate_end_to_start_m"),
    Row("laser:a", "odometry's final error ÷ filter's", "odometry_to_estimate_final_error_ratio",
        "15 cm ÷ 2.5 cm ≈ 6"),
    Row("laser:a", "RMS position error (m)", "rms_position_error_m"),
    Row("laser:a", "filter's mean NEES (consistent: 3)", "mean_nees"),
    Row("laser:a", "matched scans with the paper's ICP (0.002 m, 700 iterations)",
        "laser_match_fraction", "ICP: maximum correspondence distance 0.002, 700 iterations",
        overlay=PAPER_ICP),
    Row("laser:b", "final position error (m)", "final_position_error_m",
        "kidnapping recovered only when the new pose is not too far from the predicted one"),
    Row("laser:b", "time to recover (s; kidnapping to the error staying under 0.1 m)",
        measures.time_to_recover),
    Row("laser:c", "final position error (m)", "final_position_error_m",
        "a kidnapping into a similar surrounding: the EKF matches the wrong place"),
    Row("laser:d", "covariance inflations (P × 10)", "laser_recoveries",
        "after 100 consecutive mismatches P is multiplied by 10", EXACT),
    Row("laser:d", "kidnapping to the first inflation (s)", measures.recovery_delay),
    Row("laser:d", "share of the scans ICP matched", "laser_match_fraction"),
    Row("laser:d", "final position error (m)", "final_position_error_m",
        "a far kidnapping is not recovered"),
    Row("laser:d", "seeds still lost at the end (error > 0.5 m)", final_error_above(0.5),
        tolerance=EXACT, counts=True),
    Row("laser:d", "time to recover (s; kidnapping to the error staying under 0.1 m)",
        measures.time_to_recover),
    Row("laser:e", "filter's mean NEES (consistent: 3)", "mean_nees",
        "Fig. 5 draws 95 % ellipses; the paper states no consistency figure (its Q gives "
        "laser:a's mean NEES)"),
    Row("laser:e", "seeds with the mean NEES inside its time-average 99.9 % bounds",
        measures.mean_nees_within_time_average_bounds, tolerance=EXACT, counts=True),
    Row("laser:e", "share of steps with NEES inside its 95 % bounds", "nees_inside_fraction"),
    Row("laser:e", "RMS position error (m)", "rms_position_error_m"),
))

BEACONS = Section("beacons", (
    Row("beacons:a", "bearings per beacon per scan", measures.beacon_detection_fraction,
        "each beacon is seen with probability 50 % in each step"),
    Row("beacons:a", "EKF's RMS position error (m)", "rms_position_error_m",
        "EKF and UKF localise alike: no significant difference in the mean nor the "
        "covariances"),
    Row("beacons:a", "UKF's RMS position error (m)", "shadow_rms_position_error_m"),
    Row("beacons:a", "UKF's cost per step ÷ EKF's", "shadow_to_filter_cost_ratio",
        "a UKF step is about 4 times slower than an EKF step", TIMING, median=True),
    Row("beacons:b", "displacement to heading error < 0.1 rad (s)",
        measures.time_to_heading_within(0.1),
        "after a sudden move (1 m in x, 0.5 m in y, turned by −π/2) both filters converge "
        "towards the correct position"),
    Row("beacons:b", "displacement to position error < 0.1 m (s)",
        measures.time_to_position_within(0.1)),
    Row("beacons:b", "EKF's final position error (m)", "final_position_error_m"),
    Row("beacons:b", "UKF's final position error (m)", "shadow_final_position_error_m"),
    Row("beacons:c", "bearings per beacon per scan", measures.beacon_detection_fraction,
        "with 15 % detection (4 beacons) localisation still converges"),
    Row("beacons:c", "EKF's RMS position error (m)", "rms_position_error_m"),
    Row("beacons:c", "UKF's RMS position error (m)", "shadow_rms_position_error_m"),
))

SPEEDS = Section("speeds", (
    Row("speeds:a", "wheel speed RMS error, KF ÷ differenced", "wheel_speed_error_ratio",
        "Fig. 5: the KF improves each wheel's velocity estimate"),
    Row("speeds:b", "v RMS error, KF ÷ encoders", "velocity_error_ratio",
        "Fig. 6: the KF with two accelerometers improves v and ω"),
    Row("speeds:b", "ω RMS error, KF ÷ encoders", "turn_rate_error_ratio"),
    Row("speeds:a", "raw encoders (odometry): RMS position error (m)",
        "rms_odometry_position_error_m",
        "Fig. 7, §5: any of the filters improves the position against the raw encoder data, "
        "and the more sensors a filter uses the more it improves it"),
    Row("speeds:a", "wheel-speed KF's speeds integrated: RMS position error (m)",
        measures.wheel_kf_position("rms_wheel_kf_position_error_m")),
    Row("speeds:a", "its RMS position error ÷ raw encoders'",
        measures.wheel_kf_position("wheel_kf_position_to_odometry_ratio")),
    Row("speeds:a", "seeds where it beats raw encoders",
        ratio_below_one(measures.wheel_kf_position("wheel_kf_position_to_odometry_ratio")),
        tolerance=EXACT, counts=True),
    Row("speeds:b", "v/ω KF's speeds integrated: RMS position error (m)",
        measures.velocity_kf_position("rms_velocity_kf_position_error_m")),
    Row("speeds:b", "its RMS position error ÷ raw encoders'",
        measures.velocity_kf_position("velocity_kf_position_to_odometry_ratio")),
    Row("speeds:b", "its final position error (m)",
        measures.velocity_kf_position("final_velocity_kf_position_error_m")),
    Row("speeds:b", "seeds where it beats raw encoders",
        ratio_below_one(measures.velocity_kf_position("velocity_kf_position_to_odometry_ratio")),
        tolerance=EXACT, counts=True),
    Row("speeds:c", "5-state EKF without gyro: RMS position error (m)", "rms_position_error_m"),
    Row("speeds:c", "its RMS position error ÷ odometry's", "position_error_to_odometry_ratio"),
    Row("speeds:c", "heading RMS error ÷ odometry's", "heading_error_to_odometry_ratio"),
    Row("speeds:d", "5-state EKF with gyro: RMS position error (m)", "rms_position_error_m"),
    Row("speeds:d", "its RMS position error ÷ odometry's", "position_error_to_odometry_ratio"),
    Row("speeds:d", "its final position error (m)", "final_position_error_m"),
    Row("speeds:d", "seeds where it beats raw encoders", beats_encoders("rms_position_error_m"),
        tolerance=EXACT, counts=True),
    Row("speeds:d", "heading RMS error ÷ odometry's", "heading_error_to_odometry_ratio"),
))

COMPASS = Section("compass", (
    Row("compass:a", "max heading error (rad)", "max_heading_error_rad",
        "Fig. 3: odometry accumulates the platform's systematic errors"),
    Row("compass:b", "heading RMS error ÷ odometry's", "heading_error_to_odometry_ratio",
        "Fig. 6, a line: the filter corrects the accumulated errors (error plot only)"),
    Row("compass:b", "max heading error (rad)", "max_heading_error_rad"),
    Row("compass:b", "RMS position error (m)", "rms_position_error_m"),
    Row("compass:b", "odometry's RMS position error (m)", "rms_odometry_position_error_m"),
    Row("compass:c", "heading RMS error ÷ odometry's", "heading_error_to_odometry_ratio",
        "Fig. 7, a random path (error plot only)"),
    Row("compass:c", "max heading error (rad)", "max_heading_error_rad"),
    Row("compass:d", "heading RMS error ÷ odometry's", "heading_error_to_odometry_ratio",
        "Fig. 8, a piecewise path with stops (error plot only)"),
    Row("compass:d", "max heading error (rad)", "max_heading_error_rad"),
))

SECTIONS = (LEGOFEUP, LASER, BEACONS, SPEEDS, COMPASS)
