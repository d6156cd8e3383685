function bytes = lfup_encode_command (sequence, answers_time_us, v_right, v_left)
  % LFUP_ENCODE_COMMAND  A WheelCommand (type 0x02, 36 bytes): V1 = V_RIGHT and
  %   V2 = V_LEFT in m/s, answering the frame whose time_us is ANSWERS_TIME_US.
  bytes = [lfup_header(0x02, sequence, answers_time_us), lfup_le(double([v_right, v_left]))];
endfunction
