function [reply, reason] = lfup_decode_connect_reply (bytes)
  % LFUP_DECODE_CONNECT_REPLY  A ConnectReply (type 0x04, 44 bytes) from a datagram.
  %   REPLY has sequence, time_us, accepted (false: busy), holder ("a.b.c.d:port", the
  %   client now driving the robot), control_period (s) and time_scale (0 = lockstep).
  [header, reason] = lfup_decode_header (bytes, 0x04);
  reply = struct ();
  if (! isempty (reason))
    return;
  endif
  bytes = uint8 (bytes(:).');
  reals = lfup_from_le (bytes(29:44), "double");
  if (! all (isfinite (reals)))
    reason = "non_finite";
    return;
  endif
  reply.sequence = header.sequence;
  reply.time_us = header.time_us;
  reply.accepted = bytes(21) == 0;
  reply.holder = sprintf ("%d.%d.%d.%d:%d", bytes(25:28), lfup_from_le (bytes(23:24), "uint16"));
  reply.control_period = reals(1);
  reply.time_scale = reals(2);
endfunction
