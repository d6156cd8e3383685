function [frame, reason] = lfup_decode_frame (bytes)
  % LFUP_DECODE_FRAME  A SensorFrame (type 0x01, 36 bytes, or 52 + 9n + 2m with the
  %   extension block of the optional sensors) from a datagram.
  %   FRAME has sequence, time_us (uint64), time (s), encoders [right left] (counts,
  %   1 count = 1 degree), ir_adc [front rear] (raw 10-bit A/D), ir_valid [front rear]
  %   and the flags watchdog, paused and reset; and the optional sensors, each [] when the
  %   frame does not carry it: gyro_raw (counts), accel_raw [right_fwd right_left; left_fwd
  %   left_left] (counts), compass_deg (whole degrees), beacons, an n-by-2 matrix of
  %   [id bearing_rad] rows (zeros (0, 2): the scanner saw nothing), and laser_mm, a row of
  %   the laser scan's ranges in whole mm (values below 20 are error codes: 0 no echo,
  %   1 too near, 2 dropout).
  %   REASON is "" or why it was dropped.
  [header, reason] = lfup_decode_header (bytes, 0x01);
  frame = struct ();
  if (! isempty (reason))
    return;
  endif
  bytes = uint8 (bytes(:).');
  flags = double (lfup_from_le (bytes(33:34), "uint16"));
  frame.sequence = header.sequence;
  frame.time_us = header.time_us;
  frame.time = double (header.time_us) / 1e6;
  frame.encoders = double (lfup_from_le (bytes(21:28), "int32"));
  frame.ir_adc = double (lfup_from_le (bytes(29:32), "uint16"));
  frame.ir_valid = [bitand(flags, 1), bitand(flags, 2)] != 0;
  frame.watchdog = bitand (flags, 4) != 0;
  frame.paused = bitand (flags, 8) != 0;
  frame.reset = bitand (flags, 16) != 0;
  frame.gyro_raw = [];
  frame.accel_raw = [];
  frame.compass_deg = [];
  frame.beacons = [];
  frame.laser_mm = [];
  if (numel (bytes) > 36)
    [frame, reason] = decode_extension (bytes, frame);
  endif
endfunction

function [frame, reason] = decode_extension (bytes, frame)
  % docs/protocol.md, "SensorFrame extension"; the length (52 + 9n + 2m) was checked
  % already.
  reason = "";
  extras = double (bytes(37));
  count = double (bytes(38));
  beams = double (lfup_from_le (bytes(51:52), "uint16"));
  if (bitand (extras, 31) == 0 || count > 8 || (count > 0 && ! bitand (extras, 8))
      || beams > 1024 || (beams > 0 && ! bitand (extras, 16))
      || numel (bytes) != 52 + 9 * count + 2 * beams)
    reason = "bad_length";
    return;
  endif
  beacons = zeros (count, 2);
  for k = 1:count
    at = 52 + 9 * (k - 1);  % 0-based offset of the sighting
    beacons(k, :) = [double(bytes(at + 1)), lfup_from_le(bytes(at + 2:at + 9), "double")];
  endfor
  if (! all (isfinite (beacons(:, 2))))
    reason = "non_finite";
    return;
  endif
  if (bitand (extras, 1))
    frame.gyro_raw = double (lfup_from_le (bytes(39:40), "int16"));
  endif
  if (bitand (extras, 2))
    frame.accel_raw = reshape (double (lfup_from_le (bytes(41:48), "int16")), 2, 2).';
  endif
  if (bitand (extras, 4))
    frame.compass_deg = double (lfup_from_le (bytes(49:50), "int16"));
  endif
  if (bitand (extras, 8))
    frame.beacons = beacons;
  endif
  if (bitand (extras, 16))
    at = 52 + 9 * count;  % 0-based offset of the first range
    frame.laser_mm = double (lfup_from_le (bytes(at + 1:at + 2 * beams), "uint16"));
    frame.laser_mm = reshape (frame.laser_mm, 1, beams);
  endif
endfunction
