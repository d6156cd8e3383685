function [truth, reason] = lfup_decode_truth (bytes)
  % LFUP_DECODE_TRUTH  A GroundTruth packet (type 0x11, 100 bytes) from a datagram.
  %   TRUTH has sequence, time_us, time (s), pose [x y theta] (m, rad), v (m/s), w (rad/s),
  %   wheel_surface_speeds [right left] (m/s), ir_distances [front rear] (m),
  %   touching_wall and teleports (times the robot was moved instantly since the last
  %   reset). REASON is "" or why it was dropped.
  [header, reason] = lfup_decode_header (bytes, 0x11);
  truth = struct ();
  if (! isempty (reason))
    return;
  endif
  bytes = uint8 (bytes(:).');
  values = lfup_from_le (bytes(21:92), "double");
  if (! all (isfinite (values)))
    reason = "non_finite";
    return;
  endif
  truth.sequence = header.sequence;
  truth.time_us = header.time_us;
  truth.time = double (header.time_us) / 1e6;
  truth.pose = values(1:3);
  truth.v = values(4);
  truth.w = values(5);
  truth.wheel_surface_speeds = values(6:7);
  truth.ir_distances = values(8:9);
  truth.touching_wall = bytes(93) != 0;
  truth.teleports = double (lfup_from_le (bytes(97:100), "uint32"));
endfunction
