function big = lfup_host_is_big_endian ()
  % LFUP_HOST_IS_BIG_ENDIAN  True on a big-endian host, where the protocol's little-endian
  %   bytes must be swapped (docs/protocol.md). Asked once, then remembered.
  persistent answer;
  if (isempty (answer))
    [~, ~, endian] = computer ();
    answer = (endian == "B");
  endif
  big = answer;
endfunction
