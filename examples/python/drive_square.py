#!/usr/bin/env python3
"""Drives the simulated LegoFeup robot around the standard 2 m square from odometry alone.

Start legofeup-sim first, then run:  python3 examples/python/drive_square.py

The robot starts at (-1, -1) facing +x and drives the square centred on the origin
counter-clockwise: along y = -1 to (1, -1), turn left, up to (1, 1), ... back to the start,
where it turns to face +x again. Its pose comes from the encoder counts only (eq. 7–9 of
Pinto, Moreira & Matos 2012); ground truth is read for the final comparison, never for
control. Every --every frames it prints a line of readings; at the end a summary line:

  finished: laps=1 frames=… missing=… odometry=(x, y, θ) truth=(x, y, θ) distance_driven=… m
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from dataclasses import dataclass
from typing import List, Optional, Tuple

from legofeup_udp import (ControlError, NoReplyError, SensorFrame, SimulatorBusyError,
                          SimulatorClient, ir_distance_in_range)

# The nominal robot (docs/loop.md): what odometry assumes.
WHEEL_DIAMETER = 0.0432  # m
WHEEL_BASE = 0.12        # m, b
METRES_PER_COUNT = math.pi * WHEEL_DIAMETER / 360.0  # 1 count = 1° of wheel rotation

# The standard path: the 2 m square centred on the origin, counter-clockwise from the start.
START = (-1.0, -1.0, 0.0)
CORNERS = [(1.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0)]

# Controller.
V_REF = 0.1            # m/s along the sides
W_REF = 0.8            # rad/s, the largest turn rate asked for
MAX_WHEEL_SPEED = 0.38  # m/s, just under the motors' 170 rpm (0.385 m/s)
LOOKAHEAD = 0.2        # m: aim at the side this far ahead of the robot's projection on it
K_HEADING = 2.0        # 1/s, heading error -> turn rate while driving
K_APPROACH = 1.0       # 1/s, remaining distance -> speed near a corner
V_MIN = 0.02           # m/s, the slowest approach (so a corner is always reached)
K_TURN = 2.0           # 1/s, heading error -> turn rate when turning on the spot
W_MIN = 0.1            # rad/s, the slowest turn (so a turn always ends)
TURN_TOLERANCE = 0.01  # rad: a turn is done within this of the side's heading
SETTLE_FRAMES = 10     # frames with the motors stopped before the summary
SIM_SECONDS_PER_LAP = 150.0  # give up if a lap takes longer (e.g. the robot is stuck)


def wrap_angle(angle: float) -> float:
    """To (−π, π]."""
    wrapped = math.remainder(angle, 2.0 * math.pi)
    return math.pi if wrapped == -math.pi else wrapped


def count_difference(new: int, old: int) -> int:
    """new − old for cumulative int32 counters, taken modulo 2³² like the firmware's."""
    return ((new - old + 2**31) % 2**32) - 2**31


class Odometry:
    """Eq. 7–9: per-wheel distances from the encoder counts, the pose along the
    centred-difference heading."""

    def __init__(self, pose: Tuple[float, float, float], frame: SensorFrame) -> None:
        self.x, self.y, self.theta = pose
        self._counts = (frame.encoder_right, frame.encoder_left)
        self.distance_driven = 0.0  # m, the axle midpoint's path length

    def update(self, frame: SensorFrame) -> None:
        d1 = count_difference(frame.encoder_right, self._counts[0]) * METRES_PER_COUNT
        d2 = count_difference(frame.encoder_left, self._counts[1]) * METRES_PER_COUNT
        self._counts = (frame.encoder_right, frame.encoder_left)
        d = (d1 + d2) / 2.0
        delta_theta = (d1 - d2) / WHEEL_BASE  # wheel 1 is the right one
        heading = self.theta + delta_theta / 2.0
        self.x += d * math.cos(heading)
        self.y += d * math.sin(heading)
        self.theta = wrap_angle(self.theta + delta_theta)
        self.distance_driven += abs(d)

    @property
    def pose(self) -> Tuple[float, float, float]:
        return self.x, self.y, self.theta


@dataclass
class Leg:
    kind: str  # "turn" (on the spot, to the side's heading) or "drive" (along the side)
    side: int  # index into CORNERS of the side's end; it starts at the corner before


def side_ends(side: int) -> Tuple[Tuple[float, float], Tuple[float, float]]:
    return CORNERS[side - 1], CORNERS[side]


def side_heading(side: int) -> float:
    (ax, ay), (bx, by) = side_ends(side)
    return math.atan2(by - ay, bx - ax)


class SquareDriver:
    """Turn to the next side, drive along it to its corner; four sides a lap, then a last
    turn to face the first side again. step() returns (V, W) or None when done."""

    def __init__(self, laps: int) -> None:
        self.legs: List[Leg] = []
        for _ in range(laps):
            for side in range(len(CORNERS)):
                self.legs += [Leg("turn", side), Leg("drive", side)]
        self.legs.append(Leg("turn", 0))
        self.index = 0

    @property
    def laps_done(self) -> int:
        return self.index // (2 * len(CORNERS))

    def step(self, pose: Tuple[float, float, float]) -> Optional[Tuple[float, float]]:
        while self.index < len(self.legs):
            leg = self.legs[self.index]
            command = self._turn(leg, pose) if leg.kind == "turn" else self._drive(leg, pose)
            if command is not None:
                return command
            self.index += 1  # this leg is done: go on to the next one at once
        return None

    @staticmethod
    def _turn(leg: Leg, pose: Tuple[float, float, float]) -> Optional[Tuple[float, float]]:
        error = wrap_angle(side_heading(leg.side) - pose[2])
        if abs(error) < TURN_TOLERANCE:
            return None
        rate = min(W_REF, max(W_MIN, K_TURN * abs(error)))
        return 0.0, math.copysign(rate, error)

    @staticmethod
    def _drive(leg: Leg, pose: Tuple[float, float, float]) -> Optional[Tuple[float, float]]:
        (ax, ay), (bx, by) = side_ends(leg.side)
        length = math.hypot(bx - ax, by - ay)
        ux, uy = (bx - ax) / length, (by - ay) / length
        x, y, theta = pose
        remaining = (bx - x) * ux + (by - y) * uy  # along the side, to its end
        if remaining <= 0.0:
            return None
        cross_track = ux * (y - ay) - uy * (x - ax)  # > 0: left of the side
        # Aim at a point LOOKAHEAD ahead on the side: converges on the line without
        # the ill-defined bearing of a corner that is only millimetres away.
        desired = math.atan2(uy, ux) - math.atan2(cross_track, LOOKAHEAD)
        error = wrap_angle(desired - theta)
        w = max(-W_REF, min(W_REF, K_HEADING * error))
        v = min(V_REF * max(0.0, math.cos(error)), max(V_MIN, K_APPROACH * remaining))
        return v, w


def wheel_speeds(v: float, w: float) -> Tuple[float, float]:
    """Eq. 1: V1 (right) = V + b·W/2, V2 (left) = V − b·W/2, scaled together so that
    neither exceeds what the motors can do (keeping the path's curvature)."""
    right = v + WHEEL_BASE * w / 2.0
    left = v - WHEEL_BASE * w / 2.0
    largest = max(abs(right), abs(left))
    if largest > MAX_WHEEL_SPEED:
        right, left = right * MAX_WHEEL_SPEED / largest, left * MAX_WHEEL_SPEED / largest
    return right, left


def describe_ir(adc: int, valid: bool) -> str:
    if not valid:
        return "  — (no reading)  "
    distance = ir_distance_in_range(adc)
    if distance is None:
        return f"{adc:4d} (out of range)"
    return f"{adc:4d} = {distance * 100:5.1f} cm  "


def readings_line(frame: SensorFrame, odometry: Odometry) -> str:
    x, y, theta = odometry.pose
    front = describe_ir(frame.ir_front_adc, frame.ir_front_valid)
    rear = describe_ir(frame.ir_rear_adc, frame.ir_rear_valid)
    return (f"t={frame.time:7.2f} s  counts R={frame.encoder_right:6d} "
            f"L={frame.encoder_left:6d}  IR front {front}  rear {rear}  "
            f"odometry x={x:+.3f} y={y:+.3f} θ={math.degrees(theta):+7.2f}°")


def format_pose(pose: Tuple[float, float, float]) -> str:
    return f"({pose[0]:.3f}, {pose[1]:.3f}, {pose[2]:.3f})"


class Run:
    """One drive around the square: owns the client's robot session and cleans it up."""

    def __init__(self, client: SimulatorClient, args: argparse.Namespace) -> None:
        self.client = client
        self.args = args
        self.connected = False
        self.last_frame: Optional[SensorFrame] = None
        self.wheels = (0.0, 0.0)  # the last command sent, V1 and V2
        self.frames = 0
        # Set from the server's pace once connected: how long without a frame before the
        # last command is repeated, and before giving up.
        self.repeat_after = args.timeout
        self.frame_timeout = args.timeout

    def wait_for_frame(self) -> SensorFrame:
        """The next frame. While it is overdue (lost, or late), the last command is repeated
        every 1.5 periods, so that a lost frame or command does not trip the watchdog."""
        deadline = time.monotonic() + self.frame_timeout
        while (remaining := deadline - time.monotonic()) > 0:
            frame = self.client.next_frame(min(self.repeat_after, remaining))
            if frame is not None:
                self.last_frame = frame
                return frame
            if self.last_frame is not None:
                self.send(*self.wheels)
        raise NoReplyError(f"no sensor frame from the simulator for "
                           f"{self.frame_timeout:.1f} s")

    def reset(self) -> SensorFrame:
        """Resets to the start with the seed; returns the frame with the reset flag (time 0,
        encoders 0). Frames from before the reset are skipped; the reset is asked for again
        if its frame does not arrive."""
        # The server's first frame after it starts also has the reset flag, and it is the
        # one sent on Connect. Receive it (or a newer one, which makes it late) and read
        # what is queued, so that only the reset's own frame can be taken for it.
        if self.last_frame is None:
            self.wait_for_frame()
        for _ in range(3):
            self.client.drain_frames()
            self.client.reset(self.args.seed, START)
            deadline = time.monotonic() + self.frame_timeout
            while time.monotonic() < deadline:
                if (frame := self.wait_for_frame()).reset:
                    return frame
        raise NoReplyError("the simulator reset, but its first frame never arrived")

    def send(self, v_right: float, v_left: float) -> None:
        assert self.last_frame is not None
        self.wheels = (v_right, v_left)
        self.client.send_command(v_right, v_left, self.last_frame.time_us)

    def drive(self) -> int:
        self.client.status()  # is anybody there? (NoReplyError names the control port)
        reply = self.client.connect(self.args.timeout)
        self.connected = True
        # In lockstep the server advances at least every 100 ms on its own.
        real_period = (reply.control_period / reply.time_scale if reply.time_scale > 0
                       else 0.1)
        self.repeat_after = 1.5 * real_period
        self.frame_timeout = max(self.args.timeout, 3.0 * real_period)
        self.client.subscribe_truth()
        frame = self.reset()
        odometry = Odometry(START, frame)
        driver = SquareDriver(self.args.laps)
        time_limit = SIM_SECONDS_PER_LAP * self.args.laps
        settling = 0
        while settling < SETTLE_FRAMES:
            if frame.reset and self.frames > 0:
                raise RuntimeError("the simulator was reset by someone else during the run")
            if frame.time > time_limit:
                raise RuntimeError(f"the square was not finished within {time_limit:.0f} s "
                                   "of simulated time (is the robot stuck?)")
            wheels = self.wheels  # a paused frame repeats the last one: nothing to step
            if not frame.paused:
                self.frames += 1
                odometry.update(frame)
                command = driver.step(odometry.pose)
                if command is None:
                    settling += 1
                wheels = wheel_speeds(*(command or (0.0, 0.0)))
                if not self.args.quiet and self.frames % self.args.every == 0:
                    print(readings_line(frame, odometry), flush=True)
            # Answer every frame, paused or not: it feeds the watchdog, keeps the robot
            # ours and, in lockstep, lets the server go on at once.
            self.send(*wheels)
            self.client.latest_truth()  # drains the truth socket, renews the subscription
            frame = self.wait_for_frame()

        truth = self.client.latest_truth()
        truth_text = (format_pose((truth.x, truth.y, truth.theta)) if truth is not None
                      else "unavailable")
        print(f"finished: laps={driver.laps_done} frames={self.frames} "
              f"missing={self.client.frames.missing} odometry={format_pose(odometry.pose)} "
              f"truth={truth_text} distance_driven={odometry.distance_driven:.3f} m",
              flush=True)
        counters = self.client.status().status.counters
        print(f"server: frames_sent={counters.frames_sent} "
              f"commands_accepted={counters.commands_accepted} "
              f"commands_missing={counters.commands_missing} "
              f"watchdog_stops={counters.watchdog_stops} overruns={counters.overruns}",
              flush=True)
        return 0

    def close(self) -> None:
        """Stops the motors and gives the robot back (also after an error or Ctrl-C)."""
        if self.connected:
            if self.last_frame is not None:
                self.send(0.0, 0.0)
            self.client.unsubscribe_truth()
            self.client.disconnect()
        self.client.close()


def parse_arguments(argv: Optional[List[str]] = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        description="Drive the simulated LegoFeup robot around the 2 m square from "
                    "odometry alone (start legofeup-sim first).")
    parser.add_argument("--host", default="127.0.0.1", help="the simulator's address")
    parser.add_argument("--port", type=int, default=5600,
                        help="the robot port (default 5600); truth = port + 1, "
                             "control = port + 2 unless given")
    parser.add_argument("--truth-port", type=int, help="the ground-truth port")
    parser.add_argument("--control-port", type=int, help="the control port")
    parser.add_argument("--laps", type=int, default=1, help="laps to drive (default 1)")
    parser.add_argument("--seed", type=int, default=1,
                        help="the simulator's seed, set by a reset at the start (default 1)")
    parser.add_argument("--every", type=int, default=20,
                        help="print a line of readings every N frames (default 20 = 1 s)")
    parser.add_argument("--quiet", action="store_true",
                        help="print only the summary")
    parser.add_argument("--timeout", type=float, default=2.0,
                        help="seconds to wait for the simulator before giving up (default 2)")
    args = parser.parse_args(argv)
    if args.laps < 1 or args.every < 1 or args.timeout <= 0 or not 0 <= args.seed < 2**64:
        parser.error("--laps and --every must be at least 1, --timeout positive and "
                     "--seed in 0 … 2^64 − 1")
    return args


def main(argv: Optional[List[str]] = None) -> int:
    args = parse_arguments(argv)
    try:
        client = SimulatorClient(args.host, args.port, args.truth_port, args.control_port)
    except OSError as error:
        print(f"error: cannot reach {args.host}: {error}", file=sys.stderr)
        return 1
    run = Run(client, args)
    try:
        return run.drive()
    except KeyboardInterrupt:
        print("interrupted: stopping the robot", file=sys.stderr)
        return 130
    except SimulatorBusyError as error:
        print(f"error: {error}; try again when it disconnects", file=sys.stderr)
        return 1
    except (NoReplyError, ControlError, RuntimeError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    finally:
        run.close()


if __name__ == "__main__":
    sys.exit(main())
