function distance = lfup_ir_distance (adc, valid)
  % LFUP_IR_DISTANCE  Distance in metres seen by a Sharp GP2D120 from its raw 10-bit A/D
  %   value (paper eq. 2, docs/loop.md): D = a*(C_M/(A + C_R) - b), a = 0.01 m,
  %   C_M = 2914, C_R = 5, b = 1. NaN where the reading is not VALID or outside the
  %   trusted 4-30 cm.
  distance = 0.01 * (2914 ./ (adc + 5) - 1);
  distance(adc + 5 <= 0 | ! valid | distance < 0.04 | distance > 0.30) = NaN;
endfunction
