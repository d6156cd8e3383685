function value = lfup_from_le (bytes, class_name)
  % LFUP_FROM_LE  The CLASS_NAME value(s) ("uint16", "int32", "double", ...) stored
  %   little-endian in BYTES (a uint8 vector whose length is a multiple of the size).
  bytes = uint8 (bytes(:).');
  if (lfup_host_is_big_endian ())
    width = numel (typecast (zeros (1, 1, class_name), "uint8"));
    bytes = reshape (flipud (reshape (bytes, width, [])), 1, []);
  endif
  value = typecast (bytes, class_name);
endfunction
