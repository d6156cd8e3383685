function bytes = lfup_receive (port, timeout)
  % LFUP_RECEIVE  The next datagram on the udpport PORT as a uint8 row, or [] if none
  %   arrives within TIMEOUT seconds (0: only one already queued).
  %   On Linux a UDP socket's NumBytesAvailable is the size of the next datagram, so
  %   reading exactly that many bytes takes exactly one datagram (udpport's read would
  %   otherwise join datagrams until it has the count asked for).
  deadline = tic ();
  while (true)
    n = port.NumBytesAvailable;
    if (n > 0)
      bytes = uint8 (read (port, n, "uint8"));
      return;
    endif
    if (toc (deadline) >= timeout)
      bytes = [];
      return;
    endif
    pause (0.0005);
  endwhile
endfunction
