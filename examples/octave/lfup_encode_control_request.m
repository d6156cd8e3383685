function bytes = lfup_encode_control_request (sequence, request_id, op, varargin)
  % LFUP_ENCODE_CONTROL_REQUEST  A ControlRequest (type 0x20, 60 bytes).
  %   lfup_encode_control_request (seq, id, 1)                       % status
  %   lfup_encode_control_request (seq, id, 2, seed)                 % reset to the world's start
  %   lfup_encode_control_request (seq, id, 2, seed, [x y theta])    % reset to a pose
  %   lfup_encode_control_request (seq, id, 3) / (seq, id, 4)        % pause / resume
  %   lfup_encode_control_request (seq, id, 5, [E_d E_b slip ir_sigma])  % set noise
  %   lfup_encode_control_request (seq, id, 6, [x y theta])          % teleport
  %   lfup_encode_control_request (seq, id, 7, time_scale)           % 0 = lockstep
  flags = 0;
  arguments = zeros (1, 32, "uint8");       % what an op does not use stays zero
  switch (op)
    case 2
      arguments(1:8) = lfup_le (uint64 (varargin{1}));
      if (numel (varargin) >= 2)
        flags = 1;                          % bit 0: pose given
        arguments(9:32) = lfup_le (double (varargin{2}));
      endif
    case 5
      arguments(1:32) = lfup_le (double (varargin{1}));
    case 6
      arguments(9:32) = lfup_le (double (varargin{1}));
    case 7
      arguments(1:8) = lfup_le (double (varargin{1}));
  endswitch
  bytes = [lfup_header(0x20, sequence, 0), lfup_le(uint32(request_id)), uint8(op), ...
           uint8(flags), uint8([0 0]), arguments];
endfunction
