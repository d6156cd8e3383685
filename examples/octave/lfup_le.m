function bytes = lfup_le (value)
  % LFUP_LE  Little-endian bytes (a uint8 row) of VALUE, an integer or double array.
  %   lfup_le (uint16 (36)) is [36 0]; each element gives sizeof(class) bytes in turn.
  %   The protocol is little-endian whatever the host (docs/protocol.md).
  bytes = typecast (value(:).', "uint8");
  if (lfup_host_is_big_endian ())
    width = numel (bytes) / numel (value);
    bytes = reshape (flipud (reshape (bytes, width, [])), 1, []);
  endif
endfunction
