#!/usr/bin/env python3
"""Reproduces the five papers' results with their lessons and writes docs/papers.md.

    scripts/reproduce-papers.py [--cli PATH] [--seeds A-B] [--jobs N] [--keep DIR] [--check]

Runs every lesson step the page reports on each seed (`legofeup-cli run -e STEP -s SEED -o
DIR --no-plots -q`), measures the rows of scripts/papers/rows.py from each run's
summary.json and trace.csv, and replaces the tables between the page's markers; the text
around them is the page's own. With --check it writes nothing: it measures again on the
seeds the page names and fails, naming each number, if any lies outside the tolerance the
page states beside it. Standard library only.
"""

import argparse
import os
import sys
import tempfile
import time

from papers import page, rows
from papers.runs import MeasurementError, run_steps

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def seed_range(text):
    first, _, last = text.partition("-")
    try:
        seeds = list(range(int(first), int(last or first) + 1))
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a seed range like 1001-1010")
    if len(seeds) < 1:
        raise argparse.ArgumentTypeError(f"'{text}' names no seed")
    return seeds


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default=os.path.join(REPOSITORY, "build/release/app/legofeup-cli"),
                        help="the legofeup-cli to run (default: the release build's)")
    parser.add_argument("--page", default=os.path.join(REPOSITORY, "docs/papers.md"),
                        help="the page to write or check (default: docs/papers.md)")
    parser.add_argument("--seeds", type=seed_range,
                        help="the seeds, A-B (default: those the page names)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="runs at a time (default: the number of CPUs)")
    parser.add_argument("--keep", metavar="DIR",
                        help="keep the runs' outputs in DIR (default: a temporary directory)")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; fail if a stated number is off by more than its "
                             "tolerance")
    parser.add_argument("--quiet", action="store_true", help="no progress lines")
    return parser.parse_args()


def measure_all(args, seeds, out_dir):
    cases = set().union(*(section.cases() for section in rows.SECTIONS))
    timed = set().union(*(section.timed_cases() for section in rows.SECTIONS))
    progress = (lambda line: None) if args.quiet else (lambda line: print(line, file=sys.stderr))
    runs = run_steps(args.cli, sorted(cases - timed), seeds, out_dir, args.jobs, progress)
    # The steps whose timings the page shows run one at a time, after the others: a run
    # beside them would share their CPU and inflate one filter's time or the other's.
    runs.update(run_steps(args.cli, sorted(timed), seeds, os.path.join(out_dir, "timed"), 1,
                          progress))
    return {section.key: page.measure_section(section, runs, seeds) for section in rows.SECTIONS}


def generate(args, text, seeds, measured):
    for section in rows.SECTIONS:
        text = page.replace_block(text, section.key, seeds,
                                  page.table(section, measured[section.key], seeds))
    with open(args.page, "w", encoding="utf-8") as file:
        file.write(text)
    # What was written must pass its own check (rounding stays inside every tolerance).
    failures = check(os.path.relpath(args.page), text, measured)
    if failures:
        raise page.PageError("the written page fails its own check:\n" + "\n".join(failures))
    count = sum(len(section.rows) for section in rows.SECTIONS)
    print(f"wrote {os.path.relpath(args.page)}: {count} rows on seeds {seeds[0]}-{seeds[-1]}")


def check(path, text, measured):
    failures = []
    for section in rows.SECTIONS:
        stated = page.stated_rows(text, section.key)
        failures += page.compare(path, section, stated, measured[section.key])
    return failures


def main():
    args = arguments()
    if not os.access(args.cli, os.X_OK):
        sys.exit(f"error: {args.cli} is not an executable legofeup-cli "
                 "(build it: cmake --preset release && cmake --build --preset release "
                 "--target legofeup-cli; or pass --cli PATH)")
    try:
        with open(args.page, encoding="utf-8") as file:
            text = file.read()
        seeds = page.page_seeds(text, rows.SECTIONS)
        if args.seeds:
            if args.check and args.seeds != seeds:
                raise page.PageError(f"--check uses the page's seeds ({seeds[0]}-{seeds[-1]})")
            seeds = args.seeds
        started = time.monotonic()
        with tempfile.TemporaryDirectory(prefix="reproduce-papers-") as scratch:
            out_dir = args.keep or scratch
            os.makedirs(out_dir, exist_ok=True)
            measured = measure_all(args, seeds, out_dir)
        seconds = time.monotonic() - started
        if not args.check:
            generate(args, text, seeds, measured)
            return 0
        shown = os.path.relpath(args.page)
        failures = check(shown, text, measured)
        numbers = sum(len(s.rows) for s in rows.SECTIONS)
        if failures:
            print("\n".join(failures), file=sys.stderr)
            print(f"{shown}: {len(failures)} problems (measured in {seconds:.0f} s). If the "
                  "change is intended, rerun scripts/reproduce-papers.py and review the "
                  "page's text around the tables.", file=sys.stderr)
            return 1
        print(f"{shown}: every number of its {numbers} rows is within its tolerance "
              f"(seeds {seeds[0]}-{seeds[-1]}, {seconds:.0f} s)")
        return 0
    except (MeasurementError, page.PageError, OSError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
