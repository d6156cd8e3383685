"""What the page measures on a run's trace.csv beyond summary.json's metrics.

Each measure takes a Run and returns a number, or None when what it times never happened
on that run (the table then says on how many seeds it did).
"""

import math
import os
import tomllib

from .runs import MeasurementError

REPOSITORY = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def wrapped(angle):
    """The angle in (−π, π]."""
    return math.atan2(math.sin(angle), math.cos(angle))


def position_errors(run, x="x_est", y="y_est"):
    return [math.hypot(a - xt, b - yt) for a, b, xt, yt in
            zip(run.column(x), run.column(y), run.column("x_true"), run.column("y_true"))]


def heading_errors(run):
    return [abs(wrapped(a - b)) for a, b in zip(run.column("th_est"), run.column("th_true"))]


def touching_wall_fraction(run):
    """Share of the control steps on which the robot's body touches a wall."""
    touching = run.column("touching_wall")
    return sum(1 for value in touching if value == 1.0) / len(touching)


def position_sigma(step):
    def measure(run):
        return math.sqrt(run.column("pxx")[step] + run.column("pyy")[step])
    measure.__doc__ = f"√(Pxx + Pyy) at row {step}: the filter's own 1σ position error (m)."
    return measure


def time_to_recover(run):
    """summary.json's time_to_recover_s, None where the error never settled (there −1)."""
    seconds = run.metric("time_to_recover_s")
    return None if seconds < 0 else seconds


def _integrate(run, speeds):
    """Dead reckoning with the paper's eq. 13 from the first step's odometry pose:
    x += v·T·cos(θ + ω·T/2), y += v·T·sin(θ + ω·T/2), θ += ω·T, with T the time between
    the two rows and (v, ω) = speeds(k) the speeds row k reports for the period ending at
    it. Returns the path, one (x, y) per row."""
    times = run.column("t")
    x, y, theta = run.column("x_odo")[0], run.column("y_odo")[0], run.column("th_odo")[0]
    path = [(x, y)]
    for k in range(1, len(times)):
        v, w = speeds(k)
        if v is None or w is None:
            raise MeasurementError(
                f"{run.where()}: trace.csv line {k + 2} has no speed to integrate")
        period = times[k] - times[k - 1]
        x += v * period * math.cos(theta + 0.5 * w * period)
        y += v * period * math.sin(theta + 0.5 * w * period)
        theta += w * period
        path.append((x, y))
    return path


def _rms_to_truth(run, path):
    return math.sqrt(sum((px - xt) ** 2 + (py - yt) ** 2 for (px, py), xt, yt in
                         zip(path, run.column("x_true"), run.column("y_true"))) / len(path))


def _checked_integration(run):
    """Integrating the differenced encoder speeds must give the CLI's own odometry path
    (x_odo, y_odo): the check that this integration and the trace's columns still mean
    what it assumes."""
    v, w = run.column("v_enc"), run.column("w_enc")
    path = _integrate(run, lambda k: (v[k], w[k]))
    odometry = list(zip(run.column("x_odo"), run.column("y_odo")))
    worst = max(math.hypot(a - c, b - d) for (a, b), (c, d) in zip(path, odometry))
    if worst > 1e-5:
        raise MeasurementError(
            f"{run.where()}: integrating v_enc, w_enc with eq. 13 strays {worst:.3g} m from "
            "x_odo, y_odo: the trace's speeds or odometry changed meaning; fix "
            "scripts/papers/measures.py")


def wheel_kf_position_rms(run):
    """RMS position error (m) of the path integrated from the per-wheel KF's speeds
    (wheel_kf_right, wheel_kf_left; v = (v_R + v_L)/2, ω = (v_R − v_L)/b, eq. 14, with the
    filter's wheel base b)."""
    _checked_integration(run)
    base = float(run.setting("robot", "wheel_base"))
    right, left = run.column("wheel_kf_right"), run.column("wheel_kf_left")

    def speeds(k):
        if right[k] is None or left[k] is None:
            return None, None
        return 0.5 * (right[k] + left[k]), (right[k] - left[k]) / base

    return _rms_to_truth(run, _integrate(run, speeds))


def velocity_kf_position_rms(run):
    """RMS position error (m) of the path integrated from the (v, ω) KF's speeds with the
    accelerometers as inputs (v_kf, w_kf)."""
    _checked_integration(run)
    v, w = run.column("v_kf"), run.column("w_kf")
    return _rms_to_truth(run, _integrate(run, lambda k: (v[k], w[k])))


# How far the CLI's own integrated-position metrics may lie from this script's integration
# of the trace's speeds (relative). The two integrate the same speeds with eq. 13, but the
# CLI's RMS leaves out the first row (no speed yet, error 0), so its mean square is over
# N − 1 rows where the script's is over N: a factor √(N/(N − 1)), 1 + 1.5e-4 on the speeds
# lesson's 3350 rows (seeds 1001–1010 all differ by 1.49e-4).
INTEGRATION_AGREEMENT = 1e-3


def _cross_checked(metric, own_rms, own_metric):
    """The CLI's metric, after checking that the CLI's RMS (own_metric) agrees with this
    script's own integration of the trace (own_rms) within INTEGRATION_AGREEMENT."""
    def measure(run):
        cli, own = run.metric(own_metric), own_rms(run)
        if abs(cli - own) > INTEGRATION_AGREEMENT * max(abs(cli), abs(own)):
            raise MeasurementError(
                f"{run.where()}: summary.json's {own_metric} is {cli:.6g} m, integrating the "
                f"trace's speeds with eq. 13 gives {own:.6g} m: one of the two changed "
                "meaning; fix scripts/papers/measures.py or the CLI")
        return run.metric(metric)
    measure.__doc__ = (f"summary.json's {metric}, checked against the script's own "
                       f"integration ({own_rms.__name__}).")
    return measure


def wheel_kf_position(metric):
    """A wheel-KF position metric of summary.json, cross-checked (wheel_kf_position_rms)."""
    return _cross_checked(metric, wheel_kf_position_rms, "rms_wheel_kf_position_error_m")


def velocity_kf_position(metric):
    """A (v, ω)-KF position metric of summary.json, cross-checked (velocity_kf_position_rms)."""
    return _cross_checked(metric, velocity_kf_position_rms, "rms_velocity_kf_position_error_m")


def _first_wall_contact(run):
    """The first trace row on which the robot's body touches a wall, None if none does."""
    return next((k for k, value in enumerate(run.column("touching_wall")) if value == 1.0),
                None)


def first_wall_contact_time(run):
    """Seconds from the start to the robot's first contact with a wall (None: never)."""
    k = _first_wall_contact(run)
    return None if k is None else run.column("t")[k] - run.column("t")[0]


def position_error_at_first_contact(run):
    """The estimate's position error (m) on the row of the first wall contact."""
    k = _first_wall_contact(run)
    return None if k is None else position_errors(run)[k]


def mean_nees_within_time_average_bounds(run):
    """Whether summary.json's mean_nees lies in its time_average_nees_99_9_bounds."""
    lower, upper = run.interval("time_average_nees_99_9_bounds")
    return lower <= run.metric("mean_nees") <= upper


def _time_after(run, start, condition):
    """Seconds from `start` to the first step after it on which condition(k) holds."""
    times = run.column("t")
    for k, t in enumerate(times):
        if t > start and condition(k):
            return t - start
    return None


def displacement_time(run):
    return float(run.setting("displacement", "time"))


def _time_until_within(errors_of, limit):
    def measure(run):
        errors = errors_of(run)
        return _time_after(run, displacement_time(run), lambda k: errors[k] < limit)
    return measure


def time_to_position_within(limit):
    """Seconds from the displacement until the position error is first below limit (m)."""
    return _time_until_within(position_errors, limit)


def time_to_heading_within(limit):
    """Seconds from the displacement until the heading error is first below limit (rad)."""
    return _time_until_within(heading_errors, limit)


def recovery_delay(run):
    """Seconds from the kidnapping to the first covariance inflation (laser_recovery = 1)."""
    recovery = run.column("laser_recovery")
    return _time_after(run, float(run.setting("kidnap", "time")), lambda k: recovery[k] == 1.0)


def beacon_count(run):
    """The number of [[beacon]] tables in the run's world file (resources/worlds/NAME.toml)."""
    name = run.setting("world")
    path = os.path.join(REPOSITORY, "resources", "worlds", f"{name}.toml")
    try:
        with open(path, "rb") as file:
            beacons = tomllib.load(file).get("beacon", [])
    except (OSError, tomllib.TOMLDecodeError) as error:
        raise MeasurementError(f"{run.where()}: cannot read the world's beacons: {error}")
    if not beacons:
        raise MeasurementError(f"{run.where()}: {path} has no [[beacon]]")
    return len(beacons)


def beacon_detection_fraction(run):
    """Bearings reported per beacon per scan: Σ beacon_sightings / (beacons × scans)."""
    sightings = [value for value in run.column("beacon_sightings") if value is not None]
    if not sightings:
        raise MeasurementError(f"{run.where()}: trace.csv has no beacon scan")
    return sum(sightings) / (beacon_count(run) * len(sightings))
