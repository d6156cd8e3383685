"""Runs lesson steps with legofeup-cli and reads what they wrote, by name.

A run is `legofeup-cli run -e STEP -s SEED -o DIR --no-plots -q`. Its summary.json metrics
and trace.csv columns are looked up by name, so a reordered or extended output keeps
working, and a name that is not there stops the script with the step, the seed and the
file (a lesson changed under the page: edit scripts/papers/rows.py).
"""

import concurrent.futures
import csv
import difflib
import json
import os
import subprocess


class MeasurementError(Exception):
    """Something a row needs is not in a run's output."""


class Run:
    """One step on one seed: its summary.json, and its trace.csv read on first use."""

    def __init__(self, step, seed, directory):
        self.step = step
        self.seed = seed
        self.directory = directory
        path = os.path.join(directory, "summary.json")
        with open(path, encoding="utf-8") as file:
            self._summary = json.load(file)
        self._metrics = self._summary.get("metrics", {})
        self._rows = None
        self._columns = {}

    def where(self):
        return f"{self.step} seed {self.seed}"

    def metric(self, name):
        """A number of summary.json's "metrics" (booleans count as 0 and 1)."""
        if name not in self._metrics:
            close = difflib.get_close_matches(name, self._metrics.keys(), n=3)
            hint = f" (similar: {', '.join(close)})" if close else ""
            raise MeasurementError(
                f"{self.where()}: {self.directory}/summary.json has no metric '{name}'{hint}; "
                "docs/lessons.md lists the metrics")
        value = self._metrics[name]
        if isinstance(value, bool):
            return float(value)
        if not isinstance(value, (int, float)):
            raise MeasurementError(
                f"{self.where()}: metric '{name}' in summary.json is {value!r}, not a number")
        return float(value)

    def interval(self, name):
        """A [lower, upper] pair of summary.json's "metrics", e.g. the time-average NEES
        bounds, as a tuple of two floats."""
        value = self._metrics.get(name)
        if (not isinstance(value, list) or len(value) != 2
                or not all(isinstance(end, (int, float)) for end in value)):
            raise MeasurementError(
                f"{self.where()}: {self.directory}/summary.json's metric '{name}' is "
                f"{value!r}, not a [lower, upper] pair; docs/lessons.md lists the metrics")
        return float(value[0]), float(value[1])

    def setting(self, *path):
        """A value of summary.json's "config", e.g. setting("kidnap", "time")."""
        value = self._summary.get("config", {})
        for key in path:
            if not isinstance(value, dict) or key not in value:
                raise MeasurementError(
                    f"{self.where()}: summary.json's config has no setting {'.'.join(path)}")
            value = value[key]
        return value

    def rows(self):
        """trace.csv as a list of dicts, column name → cell text."""
        if self._rows is None:
            path = os.path.join(self.directory, "trace.csv")
            with open(path, encoding="utf-8", newline="") as file:
                self._rows = list(csv.DictReader(file))
            if not self._rows:
                raise MeasurementError(f"{self.where()}: {path} has no rows")
        return self._rows

    def column(self, name):
        """One trace.csv column as floats; an empty cell (no such sensor this step) is None."""
        if name not in self._columns:
            self._columns[name] = self._read_column(name)
        return self._columns[name]

    def _read_column(self, name):
        rows = self.rows()
        if name not in rows[0]:
            close = difflib.get_close_matches(name, rows[0].keys(), n=3)
            hint = f" (similar: {', '.join(close)})" if close else ""
            raise MeasurementError(
                f"{self.where()}: {self.directory}/trace.csv has no column '{name}'{hint}; "
                "docs/experiments.md lists the columns")
        return [float(row[name]) if row[name] != "" else None for row in rows]


def run_steps(cli, cases, seeds, out_dir, jobs, progress):
    """Runs every case, a (step, overlay) pair, on every seed, `jobs` at a time; an overlay
    is TOML text applied over the step's preset (`-c FILE`), "" for none. Returns
    {(step, overlay, seed): Run}."""
    os.makedirs(out_dir, exist_ok=True)
    overlay_files = {}
    for number, (_, overlay) in enumerate(cases):
        if overlay and overlay not in overlay_files:
            path = os.path.join(out_dir, f"overlay_{number}.toml")
            with open(path, "w", encoding="utf-8") as file:
                file.write(overlay)
            overlay_files[overlay] = path
    jobs_list = [(number, case, seed) for number, case in enumerate(cases) for seed in seeds]

    def one(job):
        number, (step, overlay), seed = job
        directory = os.path.join(out_dir, f"{step.replace(':', '_')}_{number}_{seed}")
        command = [cli, "run", "-e", step, "-s", str(seed), "-o", directory, "--no-plots", "-q"]
        if overlay:
            command += ["-c", overlay_files[overlay]]
        done = subprocess.run(command, capture_output=True, text=True, check=False)
        if done.returncode != 0:
            raise MeasurementError(
                f"{' '.join(command)} failed (exit {done.returncode}):\n{done.stderr.strip()}")
        return (step, overlay, seed), Run(step, seed, directory)

    runs = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for count, (key, run) in enumerate(pool.map(one, jobs_list), start=1):
            runs[key] = run
            progress(f"ran {count}/{len(jobs_list)}: {key[0]} seed {key[2]}")
    return runs
