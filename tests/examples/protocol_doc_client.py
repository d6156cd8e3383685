#!/usr/bin/env python3
"""A client of legofeup-sim written from docs/protocol.md and docs/arena.md alone.

Every byte layout, port, constant and rule below is the one those two pages state, not one
read from the code, so this test fails when the documents and the server disagree:

* the control stream: Status, Pause, Reset, Resume, SetTimeScale, Teleport; the reply's
  sequence and the control_requests counter counting refused requests too; refusal
  messages that fit their field as whole UTF-8;
* the placement rule: poses just inside the documented limits accepted, just outside
  refused, the limits a refusal prints accepted;
* the truth stream: a GroundTruth at once on a new subscription (none on a renewal, none
  while paused), one sequence number per period shared by every subscriber, the teleport
  count, the IR distances the arena's walls and gaps give at known poses;
* the robot stream: Connect, frames, wheel commands, the IR A/D curve, and the motors'
  first-order lag of time constant 0.05 s.

Usage (Python 3.8+, standard library only):
    protocol_doc_client.py --ready-file FILE     # a running server's ready file
    protocol_doc_client.py --ports ROBOT TRUTH CONTROL [--host 127.0.0.1]
    protocol_doc_client.py --sim PATH/TO/legofeup-sim   # starts a fresh server of its own
The server must run the standard arena, fresh or not (the test resets it). Prints one
"ok:" line per check; exits 1 at the first failure, naming what differed.
"""

import argparse
import math
import os
import random
import socket
import struct
import subprocess
import sys
import tempfile
import time

# --- docs/protocol.md: encoding, header, packets ----------------------------------------

MAGIC = b"LFUP"
VERSION = 1
HEADER = struct.Struct("<4sBBHIQ")  # magic, version, type, length, sequence, time_us
SENSOR_FRAME, WHEEL_COMMAND, CONNECT, CONNECT_REPLY, DISCONNECT = 0x01, 0x02, 0x03, 0x04, 0x05
TRUTH_SUBSCRIBE, GROUND_TRUTH, TRUTH_UNSUBSCRIBE = 0x10, 0x11, 0x12
CONTROL_REQUEST, CONTROL_REPLY = 0x20, 0x21
SIZES = {SENSOR_FRAME: 36, WHEEL_COMMAND: 36, CONNECT: 20, CONNECT_REPLY: 44, DISCONNECT: 20,
         TRUTH_SUBSCRIBE: 20, GROUND_TRUTH: 100, TRUTH_UNSUBSCRIBE: 20,
         CONTROL_REQUEST: 60, CONTROL_REPLY: 384}
MAX_DATAGRAM = 2172
OP_STATUS, OP_RESET, OP_PAUSE, OP_RESUME, OP_SET_NOISE, OP_TELEPORT, OP_SET_TIME_SCALE = range(1, 8)
RESULT_OK, RESULT_REJECTED = 0, 1
FLAG_FRONT_VALID, FLAG_REAR_VALID, FLAG_WATCHDOG, FLAG_PAUSED, FLAG_RESET = 1, 2, 4, 8, 16
COUNTERS = ["frames_sent", "truth_sent", "commands_accepted", "commands_duplicate",
            "commands_late", "commands_missing", "truncated", "bad_magic", "bad_version",
            "unknown_type", "bad_length", "oversized", "non_finite", "bad_time", "wrong_stream",
            "unexpected_peer", "watchdog_stops", "control_requests", "overruns"]
MESSAGE_OFFSET, MESSAGE_FIELD = 288, 96

# --- docs/arena.md: the standard arena and the robot ------------------------------------

WORLD_NAME = "LegoFeup standard arena"
START = (-1.0, -1.0, 0.0)
WALL_LINE = 1.21                      # every wall lies on x = ±1.21 or y = ±1.21
REACH = math.sqrt(max(0.08, 0.07) ** 2 + 0.07 ** 2)   # the chassis' reach r
LIMIT = WALL_LINE - REACH             # accepted x and y: -LIMIT ... LIMIT
CONTROL_PERIOD = 0.05
PERIOD_US = 50_000
MOTOR_TIME_CONSTANT = 0.05
NOTHING_SEEN = 0.8                    # an IR beam that meets nothing reads the ray length
BESIDE_A_WALL = 0.21 - 0.06           # path 0.21 m from a wall, sensors 0.06 m from the axle


class CheckFailed(Exception):
    pass


def check(condition, what):
    if not condition:
        raise CheckFailed(what)


def ok(what):
    print("ok: " + what, flush=True)


def header(packet_type, sequence, time_us=0):
    return HEADER.pack(MAGIC, VERSION, packet_type, SIZES[packet_type], sequence, time_us)


def open_packet(datagram, packet_type):
    """The header of a datagram of `packet_type`, after the document's checks; else None."""
    if len(datagram) > MAX_DATAGRAM or len(datagram) < HEADER.size:
        return None
    magic, version, kind, length, sequence, time_us = HEADER.unpack_from(datagram)
    if magic != MAGIC or version != VERSION or kind != packet_type:
        return None
    if length != SIZES[packet_type] or len(datagram) != length or time_us > 1 << 50:
        return None
    return sequence, time_us


class Client:
    def __init__(self, host, robot_port, truth_port, control_port):
        self.host = host
        self.ports = {"robot": robot_port, "truth": truth_port, "control": control_port}
        self.sockets = {}
        self.sequences = {}
        self.request_id = random.randrange(1 << 31)

    def socket(self, name):
        if name not in self.sockets:
            sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
            sock.bind((self.host, 0))
            self.sockets[name] = sock
        return self.sockets[name]

    def send(self, name, port_name, packet):
        self.socket(name).sendto(packet, (self.host, self.ports[port_name]))

    def next_sequence(self, name):
        self.sequences[name] = self.sequences.get(name, 0) + 1
        return self.sequences[name]

    def receive(self, name, packet_type, timeout):
        """The next datagram of `packet_type` on socket `name`, decoded header and bytes."""
        sock = self.socket(name)
        until = time.monotonic() + timeout
        while True:
            left = until - time.monotonic()
            if left <= 0:
                return None
            sock.settimeout(left)
            try:
                datagram, _ = sock.recvfrom(4096)
            except socket.timeout:
                return None
            opened = open_packet(datagram, packet_type)
            if opened is not None:
                return opened, datagram

    def drain(self, name, packet_type):
        """Everything of `packet_type` already queued on socket `name`."""
        packets = []
        while True:
            got = self.receive(name, packet_type, 0.001)
            if got is None:
                return packets
            packets.append(got)

    # --- control stream: 300 ms per try, 3 tries, the same request id for each retry

    def request(self, op, flags=0, arguments=b"\0" * 32):
        self.request_id = (self.request_id + 1) % (1 << 32)
        body = struct.pack("<IBBH", self.request_id, op, flags, 0) + arguments
        for _ in range(3):
            self.send("control", "control", header(CONTROL_REQUEST, self.next_sequence("control"))
                      + body)
            until = time.monotonic() + 0.3
            while time.monotonic() < until:
                got = self.receive("control", CONTROL_REPLY, until - time.monotonic())
                if got is not None:
                    reply = decode_reply(*got)
                    if reply["request_id"] == self.request_id:
                        return reply
        raise CheckFailed("no control reply after 3 tries: is legofeup-sim running?")

    def teleport(self, x, y, theta):
        return self.request(OP_TELEPORT, arguments=struct.pack("<Qddd", 0, x, y, theta))


def decode_reply(opened, datagram):
    (sequence, time_us) = opened
    request_id, op, result, _ = struct.unpack_from("<IBBH", datagram, 20)
    steps, period, scale, seed, e_d, e_b, slip, ir_sigma = struct.unpack_from("<QddQdddd",
                                                                              datagram, 28)
    paused, watchdog, connected = struct.unpack_from("<BBB", datagram, 92)
    world = datagram[104:136].split(b"\0", 1)[0].decode("utf-8")
    counters = dict(zip(COUNTERS, struct.unpack_from("<19Q", datagram, 136)))
    field = datagram[MESSAGE_OFFSET:MESSAGE_OFFSET + MESSAGE_FIELD]
    check(b"\0" in field, "the message field has its NUL")
    message = field.split(b"\0", 1)[0]
    try:
        text = message.decode("utf-8")   # strict: the document says whole UTF-8
    except UnicodeDecodeError as error:
        raise CheckFailed("the message %r is not UTF-8: %s" % (message, error))
    return {"sequence": sequence, "time_us": time_us, "request_id": request_id, "op": op,
            "result": result, "steps": steps, "control_period": period, "time_scale": scale,
            "paused": paused, "watchdog": watchdog, "connected": connected, "world": world,
            "counters": counters, "message_bytes": message,
            "message": text}


def decode_truth(opened, datagram):
    (sequence, time_us) = opened
    values = struct.unpack_from("<9d", datagram, 20)
    return {"sequence": sequence, "time_us": time_us, "x": values[0], "y": values[1],
            "theta": values[2], "v": values[3], "w": values[4], "right_surface": values[5],
            "left_surface": values[6], "ir_front": values[7], "ir_rear": values[8],
            "touching": datagram[92], "teleports": struct.unpack_from("<I", datagram, 96)[0]}


def decode_frame(opened, datagram):
    (sequence, time_us) = opened
    right, left, ir_front, ir_rear, flags = struct.unpack_from("<iiHHH", datagram, 20)
    return {"sequence": sequence, "time_us": time_us, "right": right, "left": left,
            "ir_front": ir_front, "ir_rear": ir_rear, "flags": flags}


def ir_distance_m(adc):
    return (2914.0 / (adc + 5) - 1.0) / 100.0     # D [cm] = 2914 / (A + 5) - 1


def subscribe(client, name):
    client.send(name, "truth", header(TRUTH_SUBSCRIBE, client.next_sequence(name)))


def truth_at_or_after(client, name, time_us, timeout=3.0):
    """The first GroundTruth on `name` whose time is at least `time_us`."""
    until = time.monotonic() + timeout
    while time.monotonic() < until:
        got = client.receive(name, GROUND_TRUTH, until - time.monotonic())
        if got is not None:
            truth = decode_truth(*got)
            if truth["time_us"] >= time_us:
                return truth
    raise CheckFailed("no GroundTruth at or after %d µs" % time_us)


# --- the checks ------------------------------------------------------------------------

def check_control_basics(client):
    status = client.request(OP_STATUS)
    check(status["result"] == RESULT_OK, "Status answered ok")
    check(status["world"] == WORLD_NAME, "world '%s', expected the standard arena" % status["world"])
    check(abs(status["control_period"] - CONTROL_PERIOD) < 1e-12, "control period 0.05 s")
    check(status["sequence"] == status["counters"]["control_requests"],
          "reply sequence %d = control_requests %d" % (status["sequence"],
                                                      status["counters"]["control_requests"]))
    ok("Status: world '%s', control period %g s, reply sequence = control_requests = %d"
       % (status["world"], status["control_period"], status["sequence"]))
    scaled = client.request(OP_SET_TIME_SCALE, arguments=struct.pack("<d", 20.0) + b"\0" * 24)
    check(scaled["result"] == RESULT_OK and scaled["time_scale"] == 20.0, "time scale 20")
    check(scaled["sequence"] == status["sequence"] + 1, "one reply number per request")


def check_truth_at_once(client):
    paused = client.request(OP_PAUSE)
    check(paused["result"] == RESULT_OK and paused["paused"] == 1, "paused")
    reset = client.request(OP_RESET, arguments=struct.pack("<Qddd", 11, 0.0, 0.0, 0.0))
    check(reset["result"] == RESULT_OK and reset["paused"] == 1 and reset["steps"] == 0,
          "a reset to the world's start keeps a paused server paused")

    subscribe(client, "truth_a")
    got = client.receive("truth_a", GROUND_TRUTH, 0.5)
    check(got is not None, "a GroundTruth at once on a new subscription, while paused")
    truth = decode_truth(*got)
    check(truth["time_us"] == 0, "the reset's time 0, got %d µs" % truth["time_us"])
    check(abs(truth["x"] - START[0]) < 1e-6 and abs(truth["y"] - START[1]) < 1e-6
          and abs(truth["theta"] - START[2]) < 1e-6, "at the start pose: %r" % truth)
    check(truth["teleports"] == 0, "no teleport since the reset")
    # arena.md: at the start the front sensor (x = -0.95) sees wall_y-, the rear one
    # (x = -1.05) passes the wall's end.
    check(abs(truth["ir_front"] - BESIDE_A_WALL) < 1e-4, "front IR %.6f m" % truth["ir_front"])
    check(abs(truth["ir_rear"] - NOTHING_SEEN) < 1e-4, "rear IR %.6f m" % truth["ir_rear"])
    ok("GroundTruth at once on subscribing, paused: t = 0, start pose (%g, %g, %g), IR front "
       "%.3f m, rear %.3f m (the wall's end)" % (truth["x"], truth["y"], truth["theta"],
                                                  truth["ir_front"], truth["ir_rear"]))
    subscribe(client, "truth_a")   # a renewal
    check(client.receive("truth_a", GROUND_TRUTH, 0.4) is None,
          "no GroundTruth on a renewal nor while paused")
    ok("no GroundTruth on a renewal, none while paused")
    resumed = client.request(OP_RESUME)
    check(resumed["result"] == RESULT_OK and resumed["paused"] == 0, "resumed")


def check_shared_truth_sequence(client):
    time.sleep(0.1)   # periods pass with one subscriber, so the latest packet is one it got
    subscribe(client, "truth_b")
    time.sleep(0.4)
    first = [decode_truth(*got) for got in client.drain("truth_a", GROUND_TRUTH)]
    second = [decode_truth(*got) for got in client.drain("truth_b", GROUND_TRUTH)]
    check(len(first) > 20 and len(second) > 20, "GroundTruth every period to both subscribers")
    offset = first[0]["sequence"] - first[0]["time_us"] // PERIOD_US
    for truth in first + second:
        check(truth["time_us"] % PERIOD_US == 0, "truth times are whole periods")
        check(truth["sequence"] - truth["time_us"] // PERIOD_US == offset,
              "sequence %d at %d µs: one number per period for everyone"
              % (truth["sequence"], truth["time_us"]))
    check(any(t["sequence"] == second[0]["sequence"] and t["time_us"] == second[0]["time_us"]
              for t in first), "the new subscriber's first packet repeats the latest one")
    ok("truth sequence: one number per period, shared (%d and %d packets, sequence - period = %d)"
       % (len(first), len(second), offset))


def check_placement(client):
    inside = LIMIT - 1e-9
    poses = [(-inside, -inside), (inside, -inside), (inside, inside), (-inside, inside),
             (-inside, 0.0), (inside, 0.0), (0.0, -inside), (0.0, inside), START[:2]]
    for i, (x, y) in enumerate(poses):
        reply = client.teleport(x, y, [0.0, 1.0, -2.5, math.pi][i % 4])
        check(reply["result"] == RESULT_OK,
              "teleport to (%.9f, %.9f) refused: %s" % (x, y, reply["message"]))
    ok("teleports accepted just inside the documented limits ±%.9f m (corners, sides)" % LIMIT)

    before = client.request(OP_STATUS)
    outside = LIMIT + 1e-6
    for n, (x, y) in enumerate([(outside, 0.0), (-outside, 0.0), (0.0, outside), (0.0, -outside)]):
        reply = client.teleport(x, y, 0.0)
        check(reply["result"] == RESULT_REJECTED, "teleport to (%.7f, %.7f) accepted" % (x, y))
        check(len(reply["message_bytes"]) <= 95, "the message fits its field")
        check(reply["message"].startswith("teleport: ") and "fits in" in reply["message"],
              "a refusal naming the limits: '%s'" % reply["message"])
        check(reply["message"].endswith(" m"), "the whole message: '%s'" % reply["message"])
        check(reply["sequence"] == before["sequence"] + 1
              and reply["counters"]["control_requests"] == reply["sequence"],
              "refused requests are numbered and counted too")
        # The printed limits, taken at their word, are accepted.
        low, high = reply["message"].rsplit("fits in ", 1)[1][:-2].split(" … ")
        check(abs(float(low) + LIMIT) < 1e-8 and abs(float(high) - LIMIT) < 1e-8,
              "printed limits %s, %s" % (low, high))
        printed = (float(high), 0.0) if n == 0 else (float(low), 0.0) if n == 1 else \
            (0.0, float(high)) if n == 2 else (0.0, float(low))
        check(client.teleport(printed[0], printed[1], 0.0)["result"] == RESULT_OK,
              "the printed limit %r is accepted" % (printed,))
        before = client.request(OP_STATUS)
    ok("teleports refused just outside, with whole UTF-8 messages such as '%s'" % reply["message"])


def teleport_and_observe(client, x, y, theta):
    reply = client.teleport(x, y, theta)
    check(reply["result"] == RESULT_OK, "teleport (%g, %g): %s" % (x, y, reply["message"]))
    # The next period's GroundTruth shows it; the IR sensors sample every 38 ms, so two
    # periods later they have seen the new place.
    return truth_at_or_after(client, "truth_a", reply["time_us"] + 2 * PERIOD_US)


def check_truth_after_teleports(client):
    subscribe(client, "truth_a")   # renewed (a subscription lapses 5 s after the last)
    client.drain("truth_a", GROUND_TRUTH)
    count = None
    # arena.md's walls and gaps, seen by the IR beams (front at x +0.05, rear at -0.05,
    # 0.06 m to the right, looking along the robot's -y).
    cases = [((-0.5, -1.0, 0.0), BESIDE_A_WALL, BESIDE_A_WALL, "beside wall_y-"),
             ((0.5, -1.0, 0.0), NOTHING_SEEN, NOTHING_SEEN, "in wall_y-'s gap"),
             ((1.0, -0.5, math.pi / 2), BESIDE_A_WALL, BESIDE_A_WALL, "beside wall_x+"),
             ((-1.0, -1.0, 0.0), BESIDE_A_WALL, NOTHING_SEEN, "the start: rear past the end")]
    for pose, front, rear, where in cases:
        truth = teleport_and_observe(client, *pose)
        check(abs(truth["x"] - pose[0]) < 1e-4 and abs(truth["y"] - pose[1]) < 1e-4
              and abs(math.remainder(truth["theta"] - pose[2], 2 * math.pi)) < 1e-4,
              "truth at the teleported pose %r: %r" % (pose, truth))
        check(count is None or truth["teleports"] == count + 1, "one teleport more")
        count = truth["teleports"]
        check(abs(truth["ir_front"] - front) < 1e-4 and abs(truth["ir_rear"] - rear) < 1e-4,
              "%s: IR %.4f, %.4f m, expected %.2f, %.2f" % (where, truth["ir_front"],
                                                           truth["ir_rear"], front, rear))
        ok("teleported to (%g, %g, %.3f), %s: truth IR front %.3f m, rear %.3f m, teleports %d"
           % (pose + (where, truth["ir_front"], truth["ir_rear"], truth["teleports"])))
    refused = client.teleport(5.0, 0.0, 0.0)
    check(refused["result"] == RESULT_REJECTED, "teleport to (5, 0) refused")
    truth = truth_at_or_after(client, "truth_a", refused["time_us"] + PERIOD_US)
    check(truth["teleports"] == count, "a refused teleport changes nothing")
    ok("a refused teleport leaves the teleport count at %d" % count)


def latest_frame(client):
    got = client.receive("robot", SENSOR_FRAME, 1.0)
    check(got is not None, "a SensorFrame")
    frames = [got] + client.drain("robot", SENSOR_FRAME)
    return decode_frame(*frames[-1])


def command(client, frame, v_right, v_left):
    client.send("robot", "robot", header(WHEEL_COMMAND, client.next_sequence("commands"),
                                         frame["time_us"]) + struct.pack("<dd", v_right, v_left))


def check_robot_stream_and_motors(client):
    subscribe(client, "truth_a")
    teleport_and_observe(client, -0.5, -1.0, 0.0)   # at rest beside wall_y-, heading +x
    lockstep = client.request(OP_SET_TIME_SCALE, arguments=b"\0" * 32)
    check(lockstep["result"] == RESULT_OK and lockstep["time_scale"] == 0.0, "lockstep")
    client.send("robot", "robot", header(CONNECT, client.next_sequence("robot")))
    got = client.receive("robot", CONNECT_REPLY, 1.0)
    check(got is not None, "a ConnectReply")
    result, _, port, address, period, scale = struct.unpack_from("<BBH4sdd", got[1], 20)
    check(result == 0 and port == client.socket("robot").getsockname()[1]
          and address == bytes([127, 0, 0, 1]), "accepted, holder = this socket")
    check(period == CONTROL_PERIOD and scale == 0.0, "ConnectReply: period 0.05 s, lockstep")
    frame = latest_frame(client)
    check(frame["flags"] & FLAG_WATCHDOG, "the watchdog bit until the first command")
    for _ in range(3):   # at rest beside wall_y-: let the IR sensors sample
        command(client, frame, 0.0, 0.0)
        frame = latest_frame(client)
    check(frame["flags"] & FLAG_FRONT_VALID and frame["flags"] & FLAG_REAR_VALID
          and not frame["flags"] & FLAG_WATCHDOG, "valid IR bits, no watchdog: %r" % frame)
    for adc in (frame["ir_front"], frame["ir_rear"]):
        check(abs(ir_distance_m(adc) - BESIDE_A_WALL) < 0.005,
              "IR A/D %d reads %.4f m, expected 0.15 m" % (adc, ir_distance_m(adc)))
    ok("Connect accepted; frames in lockstep; IR A/D %d, %d -> %.3f m, %.3f m beside wall_y-"
       % (frame["ir_front"], frame["ir_rear"], ir_distance_m(frame["ir_front"]),
          ir_distance_m(frame["ir_rear"])))

    # The motors: a step to 0.2 m/s from rest follows 0.2·(1 − e^(−t/τ)), τ = 0.05 s, from the
    # start of the period the first command lets begin. (Should the machine stall for the
    # 100 ms lockstep patience, the server steps without an answer; the command holds, so the
    # speeds still follow the curve, counted from the first period with the wheels turning.)
    speed = 0.2
    truths = []
    for _ in range(4):
        command(client, frame, speed, speed)
        frame = latest_frame(client)
        truths.append(truth_at_or_after(client, "truth_a", frame["time_us"]))
    turning = [t for t in truths if t["right_surface"] != 0.0]
    check(len(turning) >= 3, "the wheels turn after the commands: %r" % truths)
    first_us = turning[0]["time_us"]
    for truth in turning[:3]:
        k = (truth["time_us"] - first_us) // PERIOD_US + 1
        expected = speed * (1.0 - math.exp(-k * CONTROL_PERIOD / MOTOR_TIME_CONSTANT))
        for side in ("right_surface", "left_surface"):
            check(abs(truth[side] - expected) < 1e-6,
                  "after %d periods the %s speed is %.6f m/s, expected %.6f (a first-order lag)"
                  % (k, side, truth[side], expected))
        ok("motors after %d period(s): wheel surface speed %.6f m/s = 0.2·(1 − e^(−%d))"
           % (k, truth["right_surface"], k))
    command(client, frame, 0.0, 0.0)
    client.send("robot", "robot", header(DISCONNECT, client.next_sequence("robot")))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--ready-file", help="a running legofeup-sim's --ready-file")
    where.add_argument("--ports", nargs=3, type=int, metavar=("ROBOT", "TRUTH", "CONTROL"))
    where.add_argument("--sim", help="start this legofeup-sim on free ports and test it")
    parser.add_argument("--host", default="127.0.0.1")
    args = parser.parse_args()

    server = None
    scratch = None
    try:
        ready_file = args.ready_file
        if args.sim:
            scratch = tempfile.TemporaryDirectory()
            ready_file = os.path.join(scratch.name, "ready")
            # --duration stops it should this script die before it can.
            server = subprocess.Popen([args.sim, "--port", "0", "--ready-file", ready_file,
                                       "--time-scale", "20", "--duration", "120", "--quiet"])
        if ready_file:
            ports = {}
            for _ in range(100):   # the ready file appears once the server listens
                if os.path.exists(ready_file):
                    with open(ready_file) as lines:
                        ports = dict(line.strip().split("=") for line in lines if "=" in line)
                    if {"robot", "truth", "control"} <= ports.keys():
                        break
                time.sleep(0.1)
            check({"robot", "truth", "control"} <= ports.keys(), "no ready file after 10 s")
            robot, truth, control = (int(ports[name]) for name in ("robot", "truth", "control"))
        else:
            robot, truth, control = args.ports
        client = Client(args.host, robot, truth, control)
        check_control_basics(client)
        check_truth_at_once(client)
        check_shared_truth_sequence(client)
        check_placement(client)
        check_truth_after_teleports(client)
        check_robot_stream_and_motors(client)
        for name in ("truth_a", "truth_b"):
            client.send(name, "truth", header(TRUTH_UNSUBSCRIBE, client.next_sequence(name)))
        print("protocol_doc_client: every check passed")
        return 0
    except CheckFailed as failure:
        print("FAILED: %s" % failure, file=sys.stderr)
        return 1
    finally:
        if server is not None:
            server.terminate()
            server.wait(timeout=10)
        if scratch is not None:
            scratch.cleanup()


if __name__ == "__main__":
    sys.exit(main())
