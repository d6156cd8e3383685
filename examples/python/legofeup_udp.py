"""The LegoFeup UDP protocol, version 1, in plain Python (standard library only).

docs/protocol.md is the specification; this module follows it byte for byte. It has two
halves:

* encode_*/decode_* functions and small dataclasses for every packet type. Decoders check
  magic, version, type, length and finite reals, and raise DecodeError (a ValueError)
  naming the reason, the same reasons the server counts.
* SimulatorClient: one robot, truth and control socket each, with Connect/Disconnect,
  frames (classified by a 64-packet sequence window), wheel commands, control requests
  with retries, and the ground-truth subscription.

Every integer is little-endian and every real an IEEE-754 binary64, so the layouts below
are struct formats with "<".
"""

from __future__ import annotations

import math
import random
import socket
import struct
import time
from collections import deque
from dataclasses import dataclass, field, fields
from enum import IntEnum
from typing import Deque, Dict, List, Optional, Tuple

MAGIC = b"LFUP"
PROTOCOL_VERSION = 1
HEADER_SIZE = 20
# The longest packet: a sensor frame with 8 beacon sightings and a 1024-beam laser scan,
# 52 + 9·8 + 2·1024 bytes.
MAX_PACKET_SIZE = 2172
# The largest header time, 2^50 µs (35 years): up to it µs -> s -> µs gives back the same
# integer, so decoding and re-encoding never changes a time. Larger ones are dropped.
MAX_TIME_US = 1 << 50

DEFAULT_ROBOT_PORT = 5600
DEFAULT_TRUTH_PORT = 5601
DEFAULT_CONTROL_PORT = 5602

# magic, version, type, length, sequence, time_us
_HEADER = struct.Struct("<4sBBHIQ")


class PacketType(IntEnum):
    SENSOR_FRAME = 0x01       # server -> client, robot port
    WHEEL_COMMAND = 0x02      # client -> server, robot port
    CONNECT = 0x03            # client -> server, robot port
    CONNECT_REPLY = 0x04      # server -> client, robot port
    DISCONNECT = 0x05         # client -> server, robot port
    TRUTH_SUBSCRIBE = 0x10    # subscriber -> server, truth port
    GROUND_TRUTH = 0x11       # server -> subscriber, truth port
    TRUTH_UNSUBSCRIBE = 0x12  # subscriber -> server, truth port
    CONTROL_REQUEST = 0x20    # anyone -> server, control port
    CONTROL_REPLY = 0x21      # server -> requester, control port


PACKET_SIZES: Dict[PacketType, int] = {
    PacketType.SENSOR_FRAME: 36,
    PacketType.WHEEL_COMMAND: 36,
    PacketType.CONNECT: HEADER_SIZE,
    PacketType.CONNECT_REPLY: 44,
    PacketType.DISCONNECT: HEADER_SIZE,
    PacketType.TRUTH_SUBSCRIBE: HEADER_SIZE,
    PacketType.GROUND_TRUTH: 100,
    PacketType.TRUTH_UNSUBSCRIBE: HEADER_SIZE,
    PacketType.CONTROL_REQUEST: 60,
    PacketType.CONTROL_REPLY: 384,
}

BARE_TYPES = (PacketType.CONNECT, PacketType.DISCONNECT,
              PacketType.TRUTH_SUBSCRIBE, PacketType.TRUTH_UNSUBSCRIBE)

# Sensor frame flag bits (offset 32, u16).
FLAG_FRONT_VALID = 1 << 0
FLAG_REAR_VALID = 1 << 1
FLAG_WATCHDOG = 1 << 2
FLAG_PAUSED = 1 << 3
FLAG_RESET = 1 << 4

# Sensor frame extension (docs/protocol.md, "SensorFrame extension"): present when the
# frame's length is 52 + 9n + 2m instead of 36 (n beacon sightings, m laser beams). The extras
# byte (offset 36) says which optional sensors the frame carries.
EXTRA_GYRO = 1 << 0
EXTRA_ACCELEROMETERS = 1 << 1
EXTRA_COMPASS = 1 << 2
EXTRA_BEACON_SCAN = 1 << 3
EXTRA_LASER_SCAN = 1 << 4
EXTRA_SENSORS = 0x1F      # bits 0-4; bits 5-7 are reserved
FRAME_SIGHTINGS_OFFSET = 52
FRAME_SIGHTING_SIZE = 9   # u8 id + f64 bearing
FRAME_RANGE_SIZE = 2      # u16 per laser beam
MAX_BEACON_SIGHTINGS = 8
MAX_SCAN_BEAMS = 1024
# Laser ranges are whole millimetres; values below 20 are error codes.
RANGE_NO_ECHO = 0         # nothing within the maximum range
RANGE_TOO_NEAR = 1        # closer than the minimum range
RANGE_DROPOUT = 2         # the echo was too weak to measure
RANGE_FIRST_VALID = 20


def frame_length_valid(length: int) -> bool:
    """36 (the plain frame) or 52 + 9n + 2m with n = 0 … 8 sightings, m = 0 … 1024 beams."""
    if length == PACKET_SIZES[PacketType.SENSOR_FRAME]:
        return True
    for sightings in range(MAX_BEACON_SIGHTINGS + 1):
        ranges = length - FRAME_SIGHTINGS_OFFSET - FRAME_SIGHTING_SIZE * sightings
        if 0 <= ranges <= FRAME_RANGE_SIZE * MAX_SCAN_BEAMS and ranges % FRAME_RANGE_SIZE == 0:
            return True
    return False


# Control request flag bits (offset 25, u8).
FLAG_POSE_GIVEN = 1 << 0


class ControlOp(IntEnum):
    STATUS = 1
    RESET = 2
    PAUSE = 3
    RESUME = 4
    SET_NOISE = 5
    TELEPORT = 6
    SET_TIME_SCALE = 7


class ControlResult(IntEnum):
    OK = 0
    REJECTED = 1
    UNKNOWN_OP = 2


class DecodeError(ValueError):
    """A datagram to drop. `reason` is the server's counter name for it."""

    def __init__(self, reason: str, detail: str) -> None:
        super().__init__(f"{reason}: {detail}")
        self.reason = reason


# --- Sharp GP2D120 characteristic (docs/loop.md, eq. 2) ----------------------------------

IR_A = 0.01        # m per fit unit (the fit is in cm)
IR_C_M = 2914.0    # constant of multiplication
IR_C_R = 5.0       # constant of linearisation, A/D counts
IR_B = 1.0         # offset, fit units
IR_MIN_RANGE = 0.04
IR_MAX_RANGE = 0.30


def ir_distance(adc: int) -> float:
    """Eq. 2: D = a·(C_M / (A + C_R) − b) in metres (infinite when A + C_R ≤ 0)."""
    denominator = adc + IR_C_R
    if denominator <= 0:
        return math.inf
    return IR_A * (IR_C_M / denominator - IR_B)


def ir_distance_in_range(adc: int, valid: bool = True) -> Optional[float]:
    """The distance in metres if the reading is valid and within the trusted 4–30 cm."""
    if not valid:
        return None
    distance = ir_distance(adc)
    return distance if IR_MIN_RANGE <= distance <= IR_MAX_RANGE else None


# --- Helpers --------------------------------------------------------------------------------

def to_microseconds(seconds: float) -> int:
    """Seconds -> the header's microseconds (rounded; negative and NaN become 0, times
    beyond MAX_TIME_US saturate there)."""
    if not seconds > 0.0:
        return 0
    return min(round(seconds * 1e6), MAX_TIME_US)


def to_seconds(microseconds: int) -> float:
    return microseconds / 1e6


def _ipv4_bytes(address: str) -> bytes:
    return socket.inet_aton(address)  # a.b.c.d as four bytes in that order


def _ipv4_text(raw: bytes) -> str:
    return socket.inet_ntoa(raw)


def _text(raw: bytes) -> str:
    """A NUL-padded text field: the bytes up to the first NUL."""
    return raw.split(b"\0", 1)[0].decode("utf-8", errors="replace")


def _text_field(text: str, size: int) -> bytes:
    """UTF-8 bytes cut to size − 1 (so a NUL always ends it) before the first character that
    would not fit whole, NUL-padded to size."""
    cut = text.encode("utf-8")[: size - 1]
    return cut.decode("utf-8", errors="ignore").encode("utf-8").ljust(size, b"\0")


def _require_finite(*values: float) -> None:
    if not all(math.isfinite(v) for v in values):
        raise DecodeError("non_finite", "a real field is NaN or infinite")


def _header(packet_type: PacketType, sequence: int, time_us: int) -> bytes:
    return _HEADER.pack(MAGIC, PROTOCOL_VERSION, packet_type, PACKET_SIZES[packet_type],
                        sequence & 0xFFFFFFFF, time_us)


@dataclass
class Header:
    type: PacketType
    sequence: int
    time_us: int


def decode_header(datagram: bytes) -> Header:
    """Checks a datagram in the server's order; raises DecodeError with the first reason."""
    if len(datagram) > MAX_PACKET_SIZE:
        raise DecodeError("oversized", f"{len(datagram)} bytes > {MAX_PACKET_SIZE}")
    if len(datagram) < HEADER_SIZE:
        raise DecodeError("truncated", f"{len(datagram)} bytes, shorter than the header")
    magic, version, raw_type, length, sequence, time_us = _HEADER.unpack_from(datagram)
    if magic != MAGIC:
        raise DecodeError("bad_magic", f"starts with {magic!r}")
    if version != PROTOCOL_VERSION:
        raise DecodeError("bad_version", f"version {version}")
    try:
        packet_type = PacketType(raw_type)
    except ValueError:
        raise DecodeError("unknown_type", f"type 0x{raw_type:02x}") from None
    if not (frame_length_valid(length) if packet_type == PacketType.SENSOR_FRAME
            else length == PACKET_SIZES[packet_type]):
        raise DecodeError("bad_length", f"length field {length} for {packet_type.name}")
    if len(datagram) < length:
        raise DecodeError("truncated", f"{len(datagram)} of {length} bytes")
    if len(datagram) > length:
        raise DecodeError("oversized", f"{len(datagram)} bytes, length field {length}")
    if time_us > MAX_TIME_US:
        raise DecodeError("bad_time", f"time {time_us} µs beyond 2^50")
    return Header(packet_type, sequence, time_us)


def _open(datagram: bytes, *accepted: PacketType) -> Header:
    header = decode_header(datagram)
    if header.type not in accepted:
        raise DecodeError("wrong_stream", f"a {header.type.name} where it does not belong")
    return header


# --- Robot stream ---------------------------------------------------------------------------

_FRAME = struct.Struct("<iiHHHH")  # at offset 20: counts R, L, IR front, IR rear, flags, 0
# At offset 36: extras, beacon count, gyro, accel R fwd, R left, L fwd, L left, compass,
# laser beam count
_FRAME_EXTENSION = struct.Struct("<BBhhhhhhH")
_SIGHTING = struct.Struct("<Bd")  # beacon id, bearing (rad)


@dataclass
class SensorFrame:
    sequence: int
    time_us: int
    encoder_right: int  # cumulative counts, 1 count = 1° of wheel 1 (right)
    encoder_left: int   # wheel 2 (left)
    ir_front_adc: int   # raw 10-bit A/D of the front sensor (d_s1)
    ir_rear_adc: int    # rear sensor (d_s2)
    ir_front_valid: bool = True
    ir_rear_valid: bool = True
    watchdog_stopped: bool = False
    paused: bool = False
    reset: bool = False
    # Optional sensors of the further lessons: None when the frame does not carry them.
    gyro_raw: Optional[int] = None     # offset + rate in °/s + bias, ≈1 count per °/s
    # ((right forward, right left), (left forward, left left)), ≈200 counts per g
    accel_raw: Optional[Tuple[Tuple[int, int], Tuple[int, int]]] = None
    compass_deg: Optional[int] = None  # whole degrees, counter-clockwise from +x
    # [(beacon id, bearing in rad relative to the heading)]; [] = scanned, saw nothing
    beacons: Optional[List[Tuple[int, float]]] = None
    # The laser scan completed this period: each beam's range in whole mm, or an error code
    # below 20 (RANGE_NO_ECHO, RANGE_TOO_NEAR, RANGE_DROPOUT). Beam i points at
    # angle_min + i·angle_increment from the scanner's forward axis (URG-04LX: 682 beams,
    # 2π/1024 apart, centred on the axis).
    laser_mm: Optional[List[int]] = None

    @property
    def time(self) -> float:
        return to_seconds(self.time_us)

    @property
    def has_extension(self) -> bool:
        return any(v is not None for v in (self.gyro_raw, self.accel_raw, self.compass_deg,
                                           self.beacons, self.laser_mm))


def encode_frame(frame: SensorFrame) -> bytes:
    flags = ((FLAG_FRONT_VALID if frame.ir_front_valid else 0)
             | (FLAG_REAR_VALID if frame.ir_rear_valid else 0)
             | (FLAG_WATCHDOG if frame.watchdog_stopped else 0)
             | (FLAG_PAUSED if frame.paused else 0)
             | (FLAG_RESET if frame.reset else 0))
    plain = (_header(PacketType.SENSOR_FRAME, frame.sequence, frame.time_us)
             + _FRAME.pack(frame.encoder_right, frame.encoder_left,
                           frame.ir_front_adc, frame.ir_rear_adc, flags, 0))
    if not frame.has_extension:
        return plain
    sightings = (frame.beacons or [])[:MAX_BEACON_SIGHTINGS]
    ranges = (frame.laser_mm or [])[:MAX_SCAN_BEAMS]
    extras = ((EXTRA_GYRO if frame.gyro_raw is not None else 0)
              | (EXTRA_ACCELEROMETERS if frame.accel_raw is not None else 0)
              | (EXTRA_COMPASS if frame.compass_deg is not None else 0)
              | (EXTRA_BEACON_SCAN if frame.beacons is not None else 0)
              | (EXTRA_LASER_SCAN if frame.laser_mm is not None else 0))
    (right_fwd, right_left), (left_fwd, left_left) = frame.accel_raw or ((0, 0), (0, 0))
    length = (FRAME_SIGHTINGS_OFFSET + FRAME_SIGHTING_SIZE * len(sightings)
              + FRAME_RANGE_SIZE * len(ranges))
    return (plain[:6] + struct.pack("<H", length) + plain[8:]
            + _FRAME_EXTENSION.pack(extras, len(sightings), frame.gyro_raw or 0, right_fwd,
                                    right_left, left_fwd, left_left, frame.compass_deg or 0,
                                    len(ranges))
            + b"".join(_SIGHTING.pack(beacon_id, bearing) for beacon_id, bearing in sightings)
            + struct.pack(f"<{len(ranges)}H", *ranges))


def decode_frame(datagram: bytes) -> SensorFrame:
    header = _open(datagram, PacketType.SENSOR_FRAME)
    right, left, front, rear, flags, _reserved = _FRAME.unpack_from(datagram, HEADER_SIZE)
    frame = SensorFrame(header.sequence, header.time_us, right, left, front, rear,
                        bool(flags & FLAG_FRONT_VALID), bool(flags & FLAG_REAR_VALID),
                        bool(flags & FLAG_WATCHDOG), bool(flags & FLAG_PAUSED),
                        bool(flags & FLAG_RESET))
    if len(datagram) > PACKET_SIZES[PacketType.SENSOR_FRAME]:
        _decode_frame_extension(datagram, frame)
    return frame


def _decode_frame_extension(datagram: bytes, frame: SensorFrame) -> None:
    """The optional sensors after offset 36 (the length is 52 + 9n + 2m, checked already)."""
    (extras, count, gyro, right_fwd, right_left, left_fwd, left_left, compass,
     beams) = _FRAME_EXTENSION.unpack_from(datagram, 36)
    if extras & EXTRA_SENSORS == 0:
        raise DecodeError("bad_length", "extension block without any sensor flag")
    if count > MAX_BEACON_SIGHTINGS:
        raise DecodeError("bad_length", f"beacon count {count} exceeds {MAX_BEACON_SIGHTINGS}")
    if count and not extras & EXTRA_BEACON_SCAN:
        raise DecodeError("bad_length", f"beacon count {count} without the beacon-scan flag")
    if beams > MAX_SCAN_BEAMS:
        raise DecodeError("bad_length", f"laser beam count {beams} exceeds {MAX_SCAN_BEAMS}")
    if beams and not extras & EXTRA_LASER_SCAN:
        raise DecodeError("bad_length", f"laser beam count {beams} without the laser-scan flag")
    ranges_offset = FRAME_SIGHTINGS_OFFSET + FRAME_SIGHTING_SIZE * count
    needed = ranges_offset + FRAME_RANGE_SIZE * beams
    if needed != len(datagram):
        raise DecodeError("bad_length", f"beacon count {count} and laser beam count {beams} "
                                        f"need length {needed}, the length field says "
                                        f"{len(datagram)}")
    sightings = [_SIGHTING.unpack_from(datagram, FRAME_SIGHTINGS_OFFSET + FRAME_SIGHTING_SIZE * k)
                 for k in range(count)]
    _require_finite(*(bearing for _id, bearing in sightings))
    ranges = list(struct.unpack_from(f"<{beams}H", datagram, ranges_offset))
    frame.gyro_raw = gyro if extras & EXTRA_GYRO else None
    frame.accel_raw = (((right_fwd, right_left), (left_fwd, left_left))
                       if extras & EXTRA_ACCELEROMETERS else None)
    frame.compass_deg = compass if extras & EXTRA_COMPASS else None
    frame.beacons = sightings if extras & EXTRA_BEACON_SCAN else None
    frame.laser_mm = ranges if extras & EXTRA_LASER_SCAN else None


_COMMAND = struct.Struct("<dd")  # at offset 20: V1 (right), V2 (left), m/s


@dataclass
class WheelCommand:
    sequence: int
    answers_time_us: int  # the time of the newest frame the client had seen
    v_right: float        # V1, m/s
    v_left: float         # V2, m/s


def encode_command(command: WheelCommand) -> bytes:
    return (_header(PacketType.WHEEL_COMMAND, command.sequence, command.answers_time_us)
            + _COMMAND.pack(command.v_right, command.v_left))


def decode_command(datagram: bytes) -> WheelCommand:
    header = _open(datagram, PacketType.WHEEL_COMMAND)
    right, left = _COMMAND.unpack_from(datagram, HEADER_SIZE)
    _require_finite(right, left)
    return WheelCommand(header.sequence, header.time_us, right, left)


@dataclass
class BarePacket:
    """Connect, Disconnect, TruthSubscribe, TruthUnsubscribe: a header alone."""

    type: PacketType
    sequence: int
    time_us: int = 0


def encode_bare(packet: BarePacket) -> bytes:
    if packet.type not in BARE_TYPES:
        raise ValueError(f"{packet.type.name} is not a header-only packet")
    return _header(packet.type, packet.sequence, packet.time_us)


def decode_bare(datagram: bytes) -> BarePacket:
    header = _open(datagram, *BARE_TYPES)
    return BarePacket(header.type, header.sequence, header.time_us)


# result, reserved, holder port, holder IPv4, control period, time scale
_CONNECT_REPLY = struct.Struct("<BxH4sdd")


@dataclass
class ConnectReply:
    sequence: int
    time_us: int
    accepted: bool
    holder_address: str  # the client now driving the robot (the caller if accepted)
    holder_port: int
    control_period: float  # s of simulated time between frames
    time_scale: float      # simulated s per real s; 0 = lockstep


def encode_connect_reply(reply: ConnectReply) -> bytes:
    return (_header(PacketType.CONNECT_REPLY, reply.sequence, reply.time_us)
            + _CONNECT_REPLY.pack(0 if reply.accepted else 1, reply.holder_port,
                                  _ipv4_bytes(reply.holder_address),
                                  reply.control_period, reply.time_scale))


def decode_connect_reply(datagram: bytes) -> ConnectReply:
    header = _open(datagram, PacketType.CONNECT_REPLY)
    result, port, address, period, scale = _CONNECT_REPLY.unpack_from(datagram, HEADER_SIZE)
    _require_finite(period, scale)
    return ConnectReply(header.sequence, header.time_us, result == 0, _ipv4_text(address),
                        port, period, scale)


# --- Truth stream ---------------------------------------------------------------------------

# At offset 20: nine reals, touching wall, 3 reserved bytes, teleports (u32 at offset 96).
_TRUTH = struct.Struct("<9dB3xI")


@dataclass
class GroundTruth:
    sequence: int
    time_us: int
    x: float        # m, the axle midpoint
    y: float        # m
    theta: float    # rad, counter-clockwise from +x
    v: float        # actual forward speed, m/s
    w: float        # actual turn rate, rad/s
    right_wheel_surface_speed: float  # ω·r, m/s (differs from ground speed when slipping)
    left_wheel_surface_speed: float
    ir_front_distance: float  # m, what the beam really measured before noise and A/D
    ir_rear_distance: float
    touching_wall: bool
    # Times the robot was moved instantly since the last reset (teleports, kidnappings): a
    # change between two packets says it happened in between.
    teleports: int = 0

    @property
    def time(self) -> float:
        return to_seconds(self.time_us)


def encode_truth(truth: GroundTruth) -> bytes:
    return (_header(PacketType.GROUND_TRUTH, truth.sequence, truth.time_us)
            + _TRUTH.pack(truth.x, truth.y, truth.theta, truth.v, truth.w,
                          truth.right_wheel_surface_speed, truth.left_wheel_surface_speed,
                          truth.ir_front_distance, truth.ir_rear_distance,
                          1 if truth.touching_wall else 0, truth.teleports))


def decode_truth(datagram: bytes) -> GroundTruth:
    header = _open(datagram, PacketType.GROUND_TRUTH)
    (x, y, theta, v, w, right_speed, left_speed, front, rear, touching,
     teleports) = _TRUTH.unpack_from(datagram, HEADER_SIZE)
    _require_finite(x, y, theta, v, w, right_speed, left_speed, front, rear)
    return GroundTruth(header.sequence, header.time_us, x, y, theta, v, w, right_speed,
                       left_speed, front, rear, touching != 0, teleports)


# --- Control stream -------------------------------------------------------------------------

_REQUEST_HEAD = struct.Struct("<IBBH")  # at offset 20: request id, op, flags, reserved
_ARGUMENTS_OFFSET = 28
_ARGUMENTS_SIZE = 32


@dataclass
class NoiseSettings:
    wheel_diameter_ratio: float = 1.0  # E_d = D_right / D_left
    wheel_base_ratio: float = 1.0      # E_b = real / nominal wheel base
    slip_noise: float = 0.0            # m^½
    ir_noise: float = 0.0              # σ of each IR distance, m

    def values(self) -> Tuple[float, float, float, float]:
        return (self.wheel_diameter_ratio, self.wheel_base_ratio, self.slip_noise,
                self.ir_noise)


@dataclass
class ControlRequest:
    sequence: int
    request_id: int
    op: int  # a ControlOp; other values are sent as they are (the server says "unknown op")
    seed: int = 0                               # RESET
    pose: Optional[Tuple[float, float, float]] = None  # RESET (optional), TELEPORT
    noise: NoiseSettings = field(default_factory=NoiseSettings)  # SET_NOISE
    time_scale: float = 0.0                     # SET_TIME_SCALE


def _pose_values(request: ControlRequest) -> Tuple[float, float, float]:
    return request.pose if request.pose is not None else (0.0, 0.0, 0.0)


def encode_control_request(request: ControlRequest) -> bytes:
    flags = 0
    arguments = bytearray(_ARGUMENTS_SIZE)  # arguments an op does not use stay zero
    if request.op == ControlOp.RESET:
        flags = FLAG_POSE_GIVEN if request.pose is not None else 0
        struct.pack_into("<Q3d", arguments, 0, request.seed, *_pose_values(request))
    elif request.op == ControlOp.TELEPORT:
        struct.pack_into("<3d", arguments, 8, *_pose_values(request))
    elif request.op == ControlOp.SET_NOISE:
        struct.pack_into("<4d", arguments, 0, *request.noise.values())
    elif request.op == ControlOp.SET_TIME_SCALE:
        struct.pack_into("<d", arguments, 0, request.time_scale)
    # The header time of a request carries nothing; it is sent as 0.
    return (_header(PacketType.CONTROL_REQUEST, request.sequence, 0)
            + _REQUEST_HEAD.pack(request.request_id & 0xFFFFFFFF, request.op, flags, 0)
            + bytes(arguments))


def decode_control_request(datagram: bytes) -> ControlRequest:
    header = _open(datagram, PacketType.CONTROL_REQUEST)
    request_id, op, flags, _reserved = _REQUEST_HEAD.unpack_from(datagram, HEADER_SIZE)
    request = ControlRequest(header.sequence, request_id, op)
    if op in (ControlOp.RESET, ControlOp.TELEPORT):
        x, y, theta = struct.unpack_from("<3d", datagram, _ARGUMENTS_OFFSET + 8)
        _require_finite(x, y, theta)  # checked even when a Reset does not use it
        if op == ControlOp.TELEPORT or flags & FLAG_POSE_GIVEN:
            request.pose = (x, y, theta)
        if op == ControlOp.RESET:
            (request.seed,) = struct.unpack_from("<Q", datagram, _ARGUMENTS_OFFSET)
    elif op == ControlOp.SET_NOISE:
        values = struct.unpack_from("<4d", datagram, _ARGUMENTS_OFFSET)
        _require_finite(*values)
        request.noise = NoiseSettings(*values)
    elif op == ControlOp.SET_TIME_SCALE:
        (request.time_scale,) = struct.unpack_from("<d", datagram, _ARGUMENTS_OFFSET)
        _require_finite(request.time_scale)
    return request


@dataclass
class ServerCounters:
    """The 19 counters, in wire order (offset 136, 19 × u64)."""

    frames_sent: int = 0
    truth_sent: int = 0
    commands_accepted: int = 0
    commands_duplicate: int = 0
    commands_late: int = 0
    commands_missing: int = 0
    truncated: int = 0
    bad_magic: int = 0
    bad_version: int = 0
    unknown_type: int = 0
    bad_length: int = 0
    oversized: int = 0
    non_finite: int = 0
    bad_time: int = 0
    wrong_stream: int = 0
    unexpected_peer: int = 0
    watchdog_stops: int = 0
    control_requests: int = 0
    overruns: int = 0


_COUNTER_COUNT = len(fields(ServerCounters))


@dataclass
class ServerStatus:
    steps: int = 0  # control periods since the last reset
    control_period: float = 0.05
    time_scale: float = 1.0
    seed: int = 0
    noise: NoiseSettings = field(default_factory=NoiseSettings)
    paused: bool = False
    watchdog_stopped: bool = False
    client_connected: bool = False
    client_address: str = "0.0.0.0"
    client_port: int = 0
    world_name: str = ""
    counters: ServerCounters = field(default_factory=ServerCounters)


# steps, control period, time scale, seed, 4 noise reals, paused, watchdog, connected,
# reserved, client IPv4, client port, reserved, world name
_STATUS = struct.Struct("<QddQ4dBBBx4sH2x32s")
_COUNTERS = struct.Struct(f"<{_COUNTER_COUNT}Q")
_COUNTERS_OFFSET = 136
_MESSAGE_OFFSET = 288
_MESSAGE_SIZE = 96
assert HEADER_SIZE + _REQUEST_HEAD.size + _STATUS.size == _COUNTERS_OFFSET
assert _COUNTERS_OFFSET + _COUNTERS.size == _MESSAGE_OFFSET
assert _MESSAGE_OFFSET + _MESSAGE_SIZE == PACKET_SIZES[PacketType.CONTROL_REPLY]


@dataclass
class ControlReply:
    sequence: int
    time_us: int  # the server's simulated time after the request
    request_id: int
    op: int
    result: ControlResult
    status: ServerStatus
    message: str = ""  # why it was rejected


def encode_control_reply(reply: ControlReply) -> bytes:
    status = reply.status
    counters = [getattr(status.counters, f.name) for f in fields(ServerCounters)]
    return (_header(PacketType.CONTROL_REPLY, reply.sequence, reply.time_us)
            + _REQUEST_HEAD.pack(reply.request_id, reply.op, reply.result, 0)
            + _STATUS.pack(status.steps, status.control_period, status.time_scale,
                           status.seed, *status.noise.values(), status.paused,
                           status.watchdog_stopped, status.client_connected,
                           _ipv4_bytes(status.client_address), status.client_port,
                           _text_field(status.world_name, 32))
            + _COUNTERS.pack(*counters)
            + _text_field(reply.message, _MESSAGE_SIZE))


def decode_control_reply(datagram: bytes) -> ControlReply:
    header = _open(datagram, PacketType.CONTROL_REPLY)
    request_id, op, result, _reserved = _REQUEST_HEAD.unpack_from(datagram, HEADER_SIZE)
    (steps, period, scale, seed, e_d, e_b, slip, ir_sigma, paused, watchdog, connected,
     address, port, world) = _STATUS.unpack_from(datagram, HEADER_SIZE + _REQUEST_HEAD.size)
    _require_finite(period, scale, e_d, e_b, slip, ir_sigma)
    status = ServerStatus(steps, period, scale, seed,
                          NoiseSettings(e_d, e_b, slip, ir_sigma),
                          paused != 0, watchdog != 0, connected != 0,
                          _ipv4_text(address), port, _text(world),
                          ServerCounters(*_COUNTERS.unpack_from(datagram, _COUNTERS_OFFSET)))
    # Result codes this version does not know are read as "rejected", as the C++ side does.
    result_code = ControlResult(result) if result <= ControlResult.UNKNOWN_OP \
        else ControlResult.REJECTED
    message = _text(datagram[_MESSAGE_OFFSET:_MESSAGE_OFFSET + _MESSAGE_SIZE])
    return ControlReply(header.sequence, header.time_us, request_id, op, result_code, status,
                        message)


# --- Sequence window ------------------------------------------------------------------------

class SequenceWindow:
    """Classifies a stream's sequence numbers like the server does (docs/protocol.md):
    "new" (newer than all before), "duplicate" (already seen) or "late" (older, unseen).
    Gaps count as missing until a late packet fills them."""

    WINDOW = 64

    def __init__(self) -> None:
        self.newest: Optional[int] = None
        self._first = 0  # numbers before the first packet were never counted missing
        self._seen = 0  # bit i: newest − i was received
        self.accepted = 0
        self.duplicate = 0
        self.late = 0
        self.missing = 0

    def classify(self, sequence: int) -> str:
        if self.newest is None or sequence > self.newest:
            if self.newest is None:
                self._first = sequence
            else:
                advance = sequence - self.newest
                self.missing += advance - 1
                self._seen = 0 if advance >= self.WINDOW else (self._seen << advance)
            self._seen = (self._seen | 1) & ((1 << self.WINDOW) - 1)
            self.newest = sequence
            self.accepted += 1
            return "new"
        age = self.newest - sequence
        if age < self.WINDOW:
            bit = 1 << age
            if self._seen & bit:
                self.duplicate += 1
                return "duplicate"
            self._seen |= bit
            if sequence > self._first:
                self.missing -= 1  # it was counted missing when newer packets overtook it
        self.late += 1
        return "late"


# --- Client ---------------------------------------------------------------------------------

class NoReplyError(ConnectionError):
    """The simulator did not answer."""


class SimulatorBusyError(ConnectionError):
    """Another client holds the robot."""

    def __init__(self, holder: str) -> None:
        super().__init__(f"the robot is driven by another client ({holder})")
        self.holder = holder


class ControlError(RuntimeError):
    """The server answered a control request with "rejected" or "unknown op"."""

    def __init__(self, reply: ControlReply) -> None:
        op = ControlOp(reply.op).name.lower() if reply.op in set(ControlOp) else reply.op
        super().__init__(f"{op} {reply.result.name.lower()}: {reply.message}")
        self.reply = reply


class SimulatorClient:
    """A client of legofeup-sim: drives the robot, reads frames, asks for ground truth and
    sends control requests. One UDP socket per stream, each connect()ed to its server port
    so that only that port's datagrams are received (and, on Linux, a closed port shows up
    as ConnectionRefusedError, treated like silence)."""

    CONNECT_REPEAT = 0.2    # s between Connect packets until a reply arrives
    CONTROL_TRIES = 3
    CONTROL_TRY_TIMEOUT = 0.3  # s per try
    TRUTH_RENEW = 1.0       # s between TruthSubscribe packets (the lease is 5 s)

    def __init__(self, host: str = "127.0.0.1", robot_port: int = DEFAULT_ROBOT_PORT,
                 truth_port: Optional[int] = None, control_port: Optional[int] = None) -> None:
        self.host = socket.gethostbyname(host)
        self.robot_port = robot_port
        self.truth_port = truth_port if truth_port is not None else robot_port + 1
        self.control_port = control_port if control_port is not None else robot_port + 2
        self._robot = self._open_socket(self.robot_port)
        self._truth = self._open_socket(self.truth_port)
        self._control = self._open_socket(self.control_port)
        # Sequence numbers count each stream's packets. They are compared without
        # wrap-around, so start low; request ids start at random so that a rerun from
        # the same port is never mistaken for a retry of an old request.
        self._next_sequence = {"robot": 0, "command": 0, "truth": 0, "control": 0}
        self._next_request_id = random.getrandbits(32)
        self.frames = SequenceWindow()
        self.truth_window = SequenceWindow()
        self.dropped: Dict[str, int] = {}  # decode errors by reason, all streams
        self._pending: Deque[SensorFrame] = deque()
        self.connect_reply: Optional[ConnectReply] = None
        self._latest_truth: Optional[GroundTruth] = None
        self._truth_subscribed_at: Optional[float] = None

    def _open_socket(self, port: int) -> socket.socket:
        sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        sock.connect((self.host, port))
        return sock

    def _sequence(self, stream: str) -> int:
        value = self._next_sequence[stream]
        self._next_sequence[stream] = value + 1
        return value

    @staticmethod
    def _send(sock: socket.socket, packet: bytes) -> None:
        try:
            sock.send(packet)
        except ConnectionRefusedError:
            pass  # the ICMP error of an earlier datagram to a closed port; UDP carries on

    @staticmethod
    def _receive(sock: socket.socket, timeout: float) -> Optional[bytes]:
        """One datagram, or None after `timeout` s (0: only what is queued already)."""
        sock.settimeout(timeout)
        try:
            # One byte more than any valid packet, so an oversized one is recognised.
            return sock.recv(MAX_PACKET_SIZE + 1)
        except (socket.timeout, BlockingIOError, ConnectionRefusedError):
            return None

    def _count_drop(self, error: DecodeError) -> None:
        self.dropped[error.reason] = self.dropped.get(error.reason, 0) + 1

    def close(self) -> None:
        for sock in (self._robot, self._truth, self._control):
            sock.close()

    def __enter__(self) -> "SimulatorClient":
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()

    # --- robot stream -----------------------------------------------------------------------

    def connect(self, timeout: float = 2.0) -> ConnectReply:
        """Sends Connect every 200 ms until a ConnectReply arrives. Raises
        SimulatorBusyError if another client holds the robot, NoReplyError on silence."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            connect = BarePacket(PacketType.CONNECT, self._sequence("robot"))
            self._send(self._robot, encode_bare(connect))
            repeat_at = min(deadline, time.monotonic() + self.CONNECT_REPEAT)
            while (remaining := repeat_at - time.monotonic()) > 0:
                datagram = self._receive(self._robot, remaining)
                if datagram is None:
                    continue
                try:
                    header = decode_header(datagram)
                    if header.type == PacketType.SENSOR_FRAME:
                        # The server sends the current frame right after accepting; it may
                        # overtake the reply. Keep it for next_frame().
                        self._pending.append(decode_frame(datagram))
                        continue
                    reply = decode_connect_reply(datagram)
                except DecodeError as error:
                    self._count_drop(error)
                    continue
                if not reply.accepted:
                    raise SimulatorBusyError(f"{reply.holder_address}:{reply.holder_port}")
                self.connect_reply = reply
                return reply
        raise NoReplyError(f"no reply from the simulator at {self.host}:{self.robot_port} "
                           "— is legofeup-sim running?")

    def disconnect(self) -> None:
        """Releases the robot (the server also stops the motors). Nothing is answered."""
        disconnect = BarePacket(PacketType.DISCONNECT, self._sequence("robot"))
        self._send(self._robot, encode_bare(disconnect))

    def next_frame(self, timeout: float) -> Optional[SensorFrame]:
        """The next new frame within `timeout` s, or None. Duplicates and late (reordered)
        frames are counted in self.frames and skipped, never returned."""
        deadline = time.monotonic() + timeout
        while True:
            if self._pending:
                frame = self._pending.popleft()
            else:
                datagram = self._receive(self._robot, max(0.0, deadline - time.monotonic()))
                if datagram is None:
                    return None
                try:
                    frame = decode_frame(datagram)
                except DecodeError as error:
                    # Repeated ConnectReplies land here as wrong_stream; nothing is lost.
                    self._count_drop(error)
                    continue
            if self.frames.classify(frame.sequence) == "new":
                return frame

    def drain_frames(self) -> Optional[SensorFrame]:
        """Reads every frame already queued; returns the newest (None if there was none)."""
        newest = None
        while (frame := self.next_frame(0.0)) is not None:
            newest = frame
        return newest

    def send_command(self, v_right: float, v_left: float, answers_time_us: int) -> None:
        """Wheel speeds V1 (right) and V2 (left) in m/s, answering the frame of that time."""
        command = WheelCommand(self._sequence("command"), answers_time_us, v_right, v_left)
        self._send(self._robot, encode_command(command))

    # --- truth stream -----------------------------------------------------------------------

    def _send_truth(self, packet_type: PacketType) -> None:
        self._send(self._truth, encode_bare(BarePacket(packet_type, self._sequence("truth"))))

    def subscribe_truth(self) -> None:
        self._send_truth(PacketType.TRUTH_SUBSCRIBE)
        self._truth_subscribed_at = time.monotonic()

    def unsubscribe_truth(self) -> None:
        self._send_truth(PacketType.TRUTH_UNSUBSCRIBE)
        self._truth_subscribed_at = None

    def latest_truth(self) -> Optional[GroundTruth]:
        """Reads every queued GroundTruth packet and returns the newest seen so far. Renews
        the subscription when due, so call it regularly (e.g. once per frame)."""
        if (self._truth_subscribed_at is not None
                and time.monotonic() - self._truth_subscribed_at > self.TRUTH_RENEW):
            self.subscribe_truth()
        while (datagram := self._receive(self._truth, 0.0)) is not None:
            try:
                truth = decode_truth(datagram)
            except DecodeError as error:
                self._count_drop(error)
                continue
            if self.truth_window.classify(truth.sequence) == "new":
                self._latest_truth = truth
        return self._latest_truth

    # --- control stream ---------------------------------------------------------------------

    def request(self, request: ControlRequest) -> ControlReply:
        """Sends a control request (its sequence and request id are filled in here), up to
        3 tries of 300 ms with the same request id. Raises NoReplyError on silence and
        ControlError unless the result is OK."""
        request.request_id = self._next_request_id
        self._next_request_id = (self._next_request_id + 1) & 0xFFFFFFFF
        for _ in range(self.CONTROL_TRIES):
            request.sequence = self._sequence("control")
            self._send(self._control, encode_control_request(request))
            deadline = time.monotonic() + self.CONTROL_TRY_TIMEOUT
            while (remaining := deadline - time.monotonic()) > 0:
                datagram = self._receive(self._control, remaining)
                if datagram is None:
                    continue
                try:
                    reply = decode_control_reply(datagram)
                except DecodeError as error:
                    self._count_drop(error)
                    continue
                if reply.request_id != request.request_id:
                    continue  # the late answer to an earlier request
                if reply.result != ControlResult.OK:
                    raise ControlError(reply)
                return reply
        raise NoReplyError(f"no reply from the simulator at {self.host}:{self.control_port} "
                           "— is legofeup-sim running?")

    def status(self) -> ControlReply:
        return self.request(ControlRequest(0, 0, ControlOp.STATUS))

    def reset(self, seed: int, pose: Optional[Tuple[float, float, float]] = None) -> ControlReply:
        """Time 0, encoders 0, motors stopped, at `pose` (default: the world's start)."""
        return self.request(ControlRequest(0, 0, ControlOp.RESET, seed=seed, pose=pose))

    def pause(self) -> ControlReply:
        return self.request(ControlRequest(0, 0, ControlOp.PAUSE))

    def resume(self) -> ControlReply:
        return self.request(ControlRequest(0, 0, ControlOp.RESUME))

    def set_noise(self, noise: NoiseSettings) -> ControlReply:
        return self.request(ControlRequest(0, 0, ControlOp.SET_NOISE, noise=noise))

    def teleport(self, pose: Tuple[float, float, float]) -> ControlReply:
        return self.request(ControlRequest(0, 0, ControlOp.TELEPORT, pose=pose))

    def set_time_scale(self, time_scale: float) -> ControlReply:
        return self.request(ControlRequest(0, 0, ControlOp.SET_TIME_SCALE,
                                           time_scale=time_scale))


__all__: List[str] = [
    "BarePacket", "ConnectReply", "ControlError", "ControlOp", "ControlReply",
    "ControlRequest", "ControlResult", "DecodeError", "GroundTruth", "NoReplyError",
    "NoiseSettings", "PacketType", "SensorFrame", "SequenceWindow", "ServerCounters",
    "ServerStatus", "SimulatorBusyError", "SimulatorClient", "WheelCommand",
    "decode_bare", "decode_command", "decode_connect_reply", "decode_control_reply",
    "decode_control_request", "decode_frame", "decode_header", "decode_truth",
    "encode_bare", "encode_command", "encode_connect_reply", "encode_control_reply",
    "encode_control_request", "encode_frame", "encode_truth", "ir_distance",
    "ir_distance_in_range", "to_microseconds", "to_seconds",
]
