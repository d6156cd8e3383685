function bytes = lfup_header (type, sequence, time_us)
  % LFUP_HEADER  The 20-byte header of a packet of TYPE: magic "LFUP", version 1, type,
  %   length, SEQUENCE (u32) and TIME_US (u64, microseconds of simulated time).
  bytes = [uint8("LFUP"), uint8(1), uint8(type), lfup_le(uint16(lfup_packet_size(type))), ...
           lfup_le(uint32(sequence)), lfup_le(uint64(time_us))];
endfunction
