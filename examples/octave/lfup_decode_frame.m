function [frame, reason] = lfup_decode_frame (bytes)
  % LFUP_DECODE_FRAME  A SensorFrame (type 0x01, 36 bytes) from a datagram.
  %   FRAME has sequence, time_us (uint64), time (s), encoders [right left] (counts,
  %   1 count = 1 degree), ir_adc [front rear] (raw 10-bit A/D), ir_valid [front rear]
  %   and the flags watchdog, paused and reset. REASON is "" or why it was dropped.
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
endfunction
