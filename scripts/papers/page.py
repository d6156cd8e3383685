"""docs/papers.md's generated tables: measuring a section's rows over the seeds, writing the
table between the section's markers, reading back the numbers and tolerances a page states,
and comparing them with freshly measured ones.

A section's table lies between

    <!-- BEGIN generated: KEY; scripts/reproduce-papers.py writes this table, seeds A-B -->
    <!-- END generated: KEY -->

and everything outside the markers is the page's hand-written text, left as it is.
"""

import re
import statistics
from dataclasses import dataclass

from .runs import MeasurementError

NUMBER = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"
BEGIN = re.compile(r"<!-- BEGIN generated: (\w+); [^>]*?seeds (\d+)-(\d+) -->")
HEADER = ("step", "the paper", "what the lesson measures", "mean [min, max] over the seeds",
          "tolerance")


class PageError(Exception):
    """The page is not what the script can read or write."""


@dataclass
class Measured:
    """A row's numbers: mean (or median), min, max over the seeds it is defined on, or a
    count."""
    numbers: tuple  # (mean, min, max), or (count,) for a counting row, or () if never
    defined: int  # on how many seeds the measure had a value
    seeds: int
    median: bool = False  # numbers[0] is the median, not the mean

    def cell(self, counts):
        if counts:
            return f"{format_number(self.numbers[0])} of {self.seeds} seeds"
        if not self.numbers:
            return f"never (0 of {self.seeds} seeds)"
        central, low, high = (format_number(n) for n in self.numbers)
        text = f"{'median ' if self.median else ''}{central} [{low}, {high}]"
        if self.defined < self.seeds:
            text += f" on {self.defined} of {self.seeds} seeds"
        return text


def format_number(value):
    """Three significant digits, integers as they are, exponents without '+' and zeros."""
    if value == int(value) and abs(value) < 1e6:
        return str(int(value))
    text = f"{value:.3g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        text = f"{mantissa}e{int(exponent)}"
    return text


def parse_cell(text):
    """The numbers a measured cell states, in the order Measured.numbers holds them, and
    on how many seeds; None if the cell is not one the script writes."""
    if m := re.fullmatch(rf"({NUMBER}) of (\d+) seeds", text):
        return (float(m[1]),), int(m[2]), int(m[2])
    if m := re.fullmatch(r"never \(0 of (\d+) seeds\)", text):
        return (), 0, int(m[1])
    if m := re.fullmatch(rf"(?:median )?({NUMBER}) \[({NUMBER}), ({NUMBER})\]"
                         rf"( on (\d+) of (\d+) seeds)?", text):
        numbers = (float(m[1]), float(m[2]), float(m[3]))
        return (numbers, int(m[5]), int(m[6])) if m[4] else (numbers, None, None)
    return None


def measure(row, runs, seeds):
    """The row's Measured over `seeds`, from {(step, overlay, seed): Run}."""
    values = []
    for seed in seeds:
        run = runs[(row.step, row.overlay, seed)]
        value = row.measure(run) if callable(row.measure) else run.metric(row.measure)
        if row.counts:
            value = 1.0 if value else 0.0
        if value is not None:
            values.append(float(value))
    if row.counts:
        return Measured((sum(values),), len(seeds), len(seeds))
    if not values:
        return Measured((), 0, len(seeds))
    central = statistics.median(values) if row.median else sum(values) / len(values)
    return Measured((central, min(values), max(values)), len(values), len(seeds), row.median)


def table(section, measured, seeds):
    """The generated block's lines (without the markers)."""
    lines = ["| " + " | ".join(HEADER) + " |", "|" + "---|" * len(HEADER)]
    for row in section.rows:
        cells = (f"`{row.step}`", row.paper, row.quantity,
                 measured[(row.step, row.quantity)].cell(row.counts), row.tolerance)
        if any("|" in cell for cell in cells):
            raise PageError(f"a cell of {row.step} '{row.quantity}' contains '|'")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def begin_marker(key, seeds):
    return (f"<!-- BEGIN generated: {key}; scripts/reproduce-papers.py writes this table, "
            f"seeds {seeds[0]}-{seeds[-1]} -->")


def end_marker(key):
    return f"<!-- END generated: {key} -->"


def _block(text, key):
    """(start, end) of the lines strictly between KEY's markers, and its seeds."""
    lines = text.split("\n")
    begins = [i for i, line in enumerate(lines)
              if (m := BEGIN.fullmatch(line.strip())) and m[1] == key]
    ends = [i for i, line in enumerate(lines) if line.strip() == end_marker(key)]
    if len(begins) != 1 or len(ends) != 1 or ends[0] < begins[0]:
        raise PageError(f"the page needs exactly one pair of markers for '{key}' "
                        f"({begin_marker(key, [1001, 1010])} … {end_marker(key)}); "
                        f"found {len(begins)} BEGIN and {len(ends)} END")
    m = BEGIN.fullmatch(lines[begins[0]].strip())
    return begins[0], ends[0], list(range(int(m[2]), int(m[3]) + 1))


def page_seeds(text, sections):
    """The seeds the page's markers name; they must be the same for every section."""
    found = {tuple(_block(text, section.key)[2]) for section in sections}
    if len(found) != 1:
        raise PageError(f"the sections' markers name different seeds: {sorted(found)}")
    return list(found.pop())


def replace_block(text, key, seeds, lines):
    begin, end, _ = _block(text, key)
    old = text.split("\n")
    return "\n".join(old[:begin] + [begin_marker(key, seeds)] + lines + old[end:])


def stated_rows(text, key):
    """{(step, quantity): (cell, tolerance, line number)} of the page's table for KEY."""
    begin, end, _ = _block(text, key)
    stated = {}
    for number, line in enumerate(text.split("\n")[begin + 1:end], start=begin + 2):
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if len(cells) != len(HEADER) or cells[0] in ("step", "") or set(cells[0]) <= set("-"):
            continue
        stated[(cells[0].strip("`"), cells[2])] = (cells[3], cells[4], number)
    return stated


def within(stated, measured, tolerance):
    """Whether the measured number is within the tolerance text ('±10 %', '±0.5', 'exact',
    'not checked …') of the stated one."""
    if tolerance.startswith("not checked"):
        return True
    if tolerance.startswith("exact"):
        return format_number(measured) == format_number(stated)
    slack = 1e-12 * max(abs(stated), abs(measured))  # the binary representation's, no more
    if m := re.match(rf"±({NUMBER}) %", tolerance):
        return abs(measured - stated) <= float(m[1]) / 100.0 * abs(stated) + slack
    if m := re.match(rf"±({NUMBER})", tolerance):
        return abs(measured - stated) <= float(m[1]) + slack
    raise PageError(f"unknown tolerance '{tolerance}' (use '±P %', '±A', 'exact' or "
                    "'not checked (why)')")


def compare(path, section, stated, measured):
    """The failures of one section: a list of messages naming the number, what the page
    states, what was measured and the tolerance."""
    failures = []
    for row in section.rows:
        key = (row.step, row.quantity)
        now = measured[key]
        if key not in stated:
            failures.append(f"{path}: {section.key}: no row for {row.step} '{row.quantity}' "
                            f"(measured {now.cell(row.counts)}): regenerate the page")
            continue
        cell, tolerance, line = stated.pop(key)
        where = f"{path}:{line}: {row.step} '{row.quantity}'"
        parsed = parse_cell(cell)
        if parsed is None:
            failures.append(f"{where}: cannot read the stated '{cell}'")
            continue
        numbers, defined, _ = parsed
        defined = now.seeds if defined is None else defined  # no "on k of N": on every seed
        if defined != now.defined:
            failures.append(f"{where}: the page states it on {defined} seeds, it is now "
                            f"defined on {now.defined} ({now.cell(row.counts)})")
            continue
        if len(numbers) != len(now.numbers):
            failures.append(f"{where}: stated '{cell}', measured {now.cell(row.counts)}")
            continue
        names = ("count",) if row.counts else ("median" if row.median else "mean", "min", "max")
        for name, old, new in zip(names, numbers, now.numbers):
            if not within(old, new, tolerance):
                failures.append(f"{where}, {name}: the page states {format_number(old)}, "
                                f"measured {format_number(new)} (tolerance {tolerance})")
    for (step, quantity), (_, _, line) in stated.items():
        failures.append(f"{path}:{line}: {section.key}: the page states {step} '{quantity}', "
                        "which the script no longer measures: regenerate the page")
    return failures


def measure_section(section, runs, seeds):
    measured = {}
    for row in section.rows:
        try:
            measured[(row.step, row.quantity)] = measure(row, runs, seeds)
        except MeasurementError as error:
            raise MeasurementError(f"{section.key}: '{row.quantity}': {error}") from None
    return measured
