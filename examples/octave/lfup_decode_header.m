function [header, reason] = lfup_decode_header (bytes, accepted_types)
  % LFUP_DECODE_HEADER  Checks a datagram as the server does, in its order.
  %   [header, reason] = lfup_decode_header (bytes, accepted_types)
  %   HEADER has fields type, sequence (double) and time_us (uint64). REASON is "" for a
  %   good packet whose type is one of ACCEPTED_TYPES, else the name of the server's
  %   counter for the first fault: "oversized", "truncated", "bad_magic", "bad_version",
  %   "unknown_type", "bad_length", "bad_time" or "wrong_stream".
  header = struct ("type", 0, "sequence", 0, "time_us", uint64 (0));
  bytes = uint8 (bytes(:).');
  n = numel (bytes);
  if (n > 2172)                % the longest frame: 52 + 9*8 sightings + 2*1024 beams
    reason = "oversized";
  elseif (n < 20)
    reason = "truncated";
  elseif (! isequal (bytes(1:4), uint8 ("LFUP")))
    reason = "bad_magic";
  elseif (bytes(5) != 1)
    reason = "bad_version";
  elseif (lfup_packet_size (bytes(6)) == 0)
    reason = "unknown_type";
  elseif (! valid_length (bytes(6), double (lfup_from_le (bytes(7:8), "uint16"))))
    reason = "bad_length";
  elseif (n < double (lfup_from_le (bytes(7:8), "uint16")))
    reason = "truncated";
  elseif (n > double (lfup_from_le (bytes(7:8), "uint16")))
    reason = "oversized";
  elseif (lfup_from_le (bytes(13:20), "uint64") > bitshift (uint64 (1), 50))
    reason = "bad_time";
  elseif (! any (double (bytes(6)) == accepted_types))
    reason = "wrong_stream";
  else
    reason = "";
    header.type = double (bytes(6));
    header.sequence = double (lfup_from_le (bytes(9:12), "uint32"));
    header.time_us = lfup_from_le (bytes(13:20), "uint64");
  endif
endfunction

function ok = valid_length (type, length)
  % The type's size; a sensor frame may also carry the extension block: 52 + 9n + 2m,
  % n <= 8 beacon sightings, m <= 1024 laser beams.
  ranges = length - 52 - 9 * (0:8);  % bytes left for the laser ranges, for each n
  ok = length == lfup_packet_size (type) ...
       || (type == 0x01 && any (ranges >= 0 & ranges <= 2048 & mod (ranges, 2) == 0));
endfunction
