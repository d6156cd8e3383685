function [reply, reason] = lfup_decode_control_reply (bytes)
  % LFUP_DECODE_CONTROL_REPLY  A ControlReply (type 0x21, 384 bytes) from a datagram.
  %   REPLY has request_id, op, result (0 ok, 1 rejected, 2 unknown op), message, time_us
  %   and status: steps, control_period, time_scale, seed, noise [E_d E_b slip IR_sigma],
  %   paused, watchdog_stopped, client_connected, client ("a.b.c.d:port"), world_name and
  %   counters (a struct of the 19 counters, docs/protocol.md).
  [header, reason] = lfup_decode_header (bytes, 0x21);
  reply = struct ();
  if (! isempty (reason))
    return;
  endif
  bytes = uint8 (bytes(:).');
  reals = lfup_from_le (bytes(37:52), "double");     % control period, time scale
  noise = lfup_from_le (bytes(61:92), "double");     % E_d, E_b, slip, IR sigma
  if (! all (isfinite ([reals, noise])))
    reason = "non_finite";
    return;
  endif
  reply.sequence = header.sequence;
  reply.time_us = header.time_us;
  reply.request_id = double (lfup_from_le (bytes(21:24), "uint32"));
  reply.op = double (bytes(25));
  reply.result = double (bytes(26));
  if (reply.result > 2)
    reply.result = 1;                                % unknown results read as rejected
  endif
  status.steps = lfup_from_le (bytes(29:36), "uint64");
  status.control_period = reals(1);
  status.time_scale = reals(2);
  status.seed = lfup_from_le (bytes(53:60), "uint64");
  status.noise = noise;
  status.paused = bytes(93) != 0;
  status.watchdog_stopped = bytes(94) != 0;
  status.client_connected = bytes(95) != 0;
  status.client = sprintf ("%d.%d.%d.%d:%d", bytes(97:100), lfup_from_le (bytes(101:102), "uint16"));
  status.world_name = nul_terminated (bytes(105:136));
  names = {"frames_sent", "truth_sent", "commands_accepted", "commands_duplicate", ...
           "commands_late", "commands_missing", "truncated", "bad_magic", "bad_version", ...
           "unknown_type", "bad_length", "oversized", "non_finite", "bad_time", ...
           "wrong_stream", "unexpected_peer", "watchdog_stops", "control_requests", ...
           "overruns"};
  values = lfup_from_le (bytes(137:288), "uint64");
  for i = 1:numel (names)
    status.counters.(names{i}) = values(i);
  endfor
  reply.status = status;
  reply.message = nul_terminated (bytes(289:384));
endfunction

function text = nul_terminated (bytes)
  end_at = find (bytes == 0, 1);
  if (! isempty (end_at))
    bytes = bytes(1:end_at - 1);
  endif
  text = char (bytes);
endfunction
