function n = lfup_packet_size (type)
  % LFUP_PACKET_SIZE  The exact length in bytes of a packet of TYPE, or 0 for a type
  %   protocol version 1 does not define (docs/protocol.md, "Packets").
  switch (double (type))
    case {0x01, 0x02}               % SensorFrame, WheelCommand
      n = 36;
    case {0x03, 0x05, 0x10, 0x12}   % Connect, Disconnect, TruthSubscribe, TruthUnsubscribe
      n = 20;
    case 0x04                       % ConnectReply
      n = 44;
    case 0x11                       % GroundTruth
      n = 100;
    case 0x20                       % ControlRequest
      n = 60;
    case 0x21                       % ControlReply
      n = 384;
    otherwise
      n = 0;
  endswitch
endfunction
