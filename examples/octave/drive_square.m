function drive_square (varargin)
  % DRIVE_SQUARE  Drive the simulated LegoFeup robot around the standard 2 m square from
  %   odometry alone, over UDP (docs/protocol.md). Start legofeup-sim first, then:
  %
  %     cd examples/octave
  %     octave --no-gui --eval "drive_square"
  %     octave --no-gui --eval "drive_square ('port', 5600, 'laps', 1, 'seed', 7)"
  %
  %   Options, as name/value pairs: host ("127.0.0.1"), port (5600, the robot port),
  %   truth_port (port + 1), control_port (port + 2), laps (1), seed (1, set by a reset
  %   at the start), every (20: a line of readings every so many frames), quiet (false:
  %   true prints the summary only), timeout (2 s without the simulator before giving up).
  %
  %   The robot starts at (-1, -1) facing +x and drives the square centred on the origin
  %   counter-clockwise, turning on the spot at each corner, then turns to face +x again.
  %   Its pose comes from the encoder counts only (eq. 7-9 of the paper); ground truth is
  %   read for the final comparison. The last line is a summary:
  %
  %     finished: laps=1 frames=... missing=... odometry=(x, y, θ) truth=(x, y, θ) distance_driven=... m
  %
  %   Needs GNU Octave 7 and the instrument-control package (udpport). Octave answers a
  %   frame in about a millisecond: run the simulator in lockstep (--time-scale 0) or at
  %   a time scale up to about 10.

  opt = parse_options (varargin);
  pkg load instrument-control

  start = [-1, -1, 0];                              % x, y (m), theta (rad)
  settle_frames = 10;                               % motors stopped before the summary
  link = open_link (opt);
  connected = false;
  last_time_us = uint64 (0);
  unwind_protect
    % Is anybody there? (The error names the control port.)
    link = control_request (link, 1);
    [link, reply] = connect_robot (link, opt.timeout);
    connected = true;
    if (reply.time_scale > 0)
      real_period = reply.control_period / reply.time_scale;
    else
      real_period = 0.1;                            % lockstep: the server's patience
    endif
    % How long without a frame before the last command is repeated (so that a lost frame
    % or command does not trip the watchdog), and before giving up.
    link.repeat_after = 1.5 * real_period;
    frame_timeout = max (opt.timeout, 3 * real_period);
    link = subscribe_truth (link);
    [link, frame] = reset_robot (link, opt.seed, start, frame_timeout);
    last_time_us = frame.time_us;

    pose = start;
    counts = frame.encoders;
    distance_driven = 0;
    legs = square_legs (opt.laps);
    leg = 1;
    frames = 0;
    settling = 0;
    time_limit = 150 * opt.laps;                    % s of simulated time: stuck?
    while (settling < settle_frames)
      if (frame.reset && frames > 0)
        error ("drive_square: the simulator was reset by someone else during the run");
      endif
      if (frame.time > time_limit)
        error ("drive_square: the square was not finished within %.0f s of simulated time (is the robot stuck?)", time_limit);
      endif
      wheels = link.wheels;                         % a paused frame repeats the last one
      if (isempty (wheels))
        wheels = [0, 0];
      endif
      if (! frame.paused)
        frames += 1;
        [pose, counts, travelled] = odometry (pose, counts, frame.encoders);
        distance_driven += travelled;
        [command, leg] = square_step (legs, leg, pose);   % V, W
        if (leg > numel (legs))
          settling += 1;
        endif
        wheels = wheel_speeds (command);
        if (! opt.quiet && mod (frames, opt.every) == 0)
          print_readings (frame, pose);
        endif
      endif
      % Answer every frame, paused or not: it feeds the watchdog, keeps the robot ours
      % and, in lockstep, lets the server go on at once.
      link = send_command (link, wheels, frame.time_us);
      link = read_truth (link);
      [link, frame] = next_frame (link, frame_timeout);
      last_time_us = frame.time_us;
    endwhile

    if (isempty (link.truth_latest))
      truth_text = "unavailable";
    else
      truth_text = format_pose (link.truth_latest.pose);
    endif
    printf ("finished: laps=%d frames=%d missing=%d odometry=%s truth=%s distance_driven=%.3f m\n",
            opt.laps, frames, link.frames.missing, format_pose (pose), truth_text,
            distance_driven);
    [link, reply] = control_request (link, 1);
    c = reply.status.counters;
    printf ("server: frames_sent=%d commands_accepted=%d commands_missing=%d watchdog_stops=%d overruns=%d\n",
            c.frames_sent, c.commands_accepted, c.commands_missing, c.watchdog_stops,
            c.overruns);
  unwind_protect_cleanup
    % Also after an error or Ctrl-C: stop the motors and give the robot back.
    if (connected)
      link = send_command (link, [0, 0], last_time_us);
      link = send_bare (link, "truth", 0x12);       % TruthUnsubscribe
      link = send_bare (link, "robot", 0x05);       % Disconnect
    endif
  end_unwind_protect
endfunction

% --- options and sockets -------------------------------------------------------------------

function opt = parse_options (args)
  opt = struct ("host", "127.0.0.1", "port", 5600, "truth_port", [], "control_port", [],
                "laps", 1, "seed", 1, "every", 20, "quiet", false, "timeout", 2);
  if (mod (numel (args), 2) != 0)
    error ("drive_square: options come as name/value pairs");
  endif
  for i = 1:2:numel (args)
    name = lower (args{i});
    if (! isfield (opt, name))
      error ("drive_square: unknown option '%s'", args{i});
    endif
    opt.(name) = args{i + 1};
  endfor
  if (isempty (opt.truth_port))
    opt.truth_port = opt.port + 1;
  endif
  if (isempty (opt.control_port))
    opt.control_port = opt.port + 2;
  endif
  if (opt.laps < 1 || opt.every < 1 || opt.timeout <= 0 || opt.seed < 0)
    error ("drive_square: laps and every must be at least 1, timeout positive, seed >= 0");
  endif
endfunction

function link = open_link (opt)
  % One socket per stream; the server answers each where it came from.
  link.host = opt.host;
  link.ports = struct ("robot", opt.port, "truth", opt.truth_port, "control", opt.control_port);
  link.robot = udpport ();
  link.truth = udpport ();
  link.control = udpport ();
  % Sequence numbers count each stream's packets; request ids start at random so that a
  % rerun from the same port is never taken for a retry of an old request.
  link.sequence = struct ("robot", 0, "command", 0, "truth", 0, "control", 0);
  link.request_id = randi ([0, 2^32 - 1]);
  link.frames = struct ("newest", [], "first", 0, "seen", [], "missing", 0,
                        "duplicate", 0, "late", 0);
  link.truth_latest = [];
  link.truth_renewed = tic ();
  link.wheels = [];                                 % the last command sent, [V1 V2]
  link.answers_time_us = uint64 (0);
  link.repeat_after = opt.timeout;
endfunction

function link = send (link, stream, bytes)
  write (link.(stream), bytes, link.host, link.ports.(stream));
endfunction

function link = send_bare (link, stream, type)
  % Connect, Disconnect, TruthSubscribe, TruthUnsubscribe: a header alone.
  link = send (link, stream, lfup_header (type, link.sequence.(stream), 0));
  link.sequence.(stream) += 1;
endfunction

function link = send_command (link, wheels, answers_time_us)
  link = send (link, "robot", lfup_encode_command (link.sequence.command, answers_time_us,
                                                   wheels(1), wheels(2)));
  link.sequence.command += 1;
  link.wheels = wheels;
  link.answers_time_us = answers_time_us;
endfunction

% --- robot stream --------------------------------------------------------------------------

function [link, reply] = connect_robot (link, timeout)
  % Connect every 200 ms until a ConnectReply arrives. Frames arriving meanwhile are
  % dropped: the reset that follows gives the reference.
  started = tic ();
  while (toc (started) < timeout)
    link = send_bare (link, "robot", 0x03);
    sent = tic ();
    while (toc (sent) < 0.2)
      bytes = lfup_receive (link.robot, 0.2 - toc (sent));
      if (isempty (bytes))
        continue;
      endif
      [reply, reason] = lfup_decode_connect_reply (bytes);
      if (isempty (reason))
        if (! reply.accepted)
          error ("drive_square: the robot is driven by another client (%s); try again when it disconnects",
                 reply.holder);
        endif
        return;
      endif
    endwhile
  endwhile
  error ("drive_square: no reply from the simulator at %s:%d — is legofeup-sim running?",
         link.host, link.ports.robot);
endfunction

function [link, frame] = next_frame (link, timeout)
  % The next new frame; duplicates and late (reordered) frames are counted and skipped.
  % While it is overdue, the last command is repeated every LINK.repeat_after seconds.
  started = tic ();
  while (true)
    if (toc (started) >= timeout)
      error ("drive_square: no sensor frame from the simulator for %.1f s", timeout);
    endif
    bytes = lfup_receive (link.robot, min (link.repeat_after, timeout - toc (started)));
    if (isempty (bytes))
      if (! isempty (link.wheels))
        link = send_command (link, link.wheels, link.answers_time_us);
      endif
      continue;
    endif
    [frame, reason] = lfup_decode_frame (bytes);
    if (isempty (reason))
      [link.frames, is_new] = classify (link.frames, frame.sequence);
      if (is_new)
        return;
      endif
    endif
  endwhile
endfunction

function [w, is_new] = classify (w, sequence)
  % The 64-packet sequence window of docs/protocol.md ("Sequence numbers").
  if (isempty (w.newest) || sequence > w.newest)
    if (isempty (w.newest))
      w.first = sequence;
    else
      w.missing += sequence - w.newest - 1;
    endif
    w.newest = sequence;
    w.seen = [w.seen(w.seen > sequence - 64), sequence];
    is_new = true;
  elseif (any (w.seen == sequence))
    w.duplicate += 1;
    is_new = false;
  else
    if (sequence > w.newest - 64 && sequence > w.first)
      w.missing -= 1;                               % it was counted missing when overtaken
      w.seen(end + 1) = sequence;
    endif
    w.late += 1;
    is_new = false;
  endif
endfunction

function [link, frame] = reset_robot (link, seed, start, timeout)
  % Reset to START with SEED and return the frame with the reset flag. The server's first
  % frame after it starts also has that flag, and it is the one sent on Connect: receive
  % it (or a newer one, which makes it late) and read what is queued, so that only the
  % reset's own frame can be taken for it.
  link = next_frame (link, timeout);
  for attempt = 1:3
    while (! isempty (lfup_receive (link.robot, 0)))
    endwhile
    link = control_request (link, 2, seed, start);
    started = tic ();
    while (toc (started) < timeout)
      [link, frame] = next_frame (link, timeout);
      if (frame.reset)
        return;
      endif
    endwhile
  endfor
  error ("drive_square: the simulator reset, but its first frame never arrived");
endfunction

% --- truth and control streams -------------------------------------------------------------

function link = subscribe_truth (link)
  link = send_bare (link, "truth", 0x10);
  link.truth_renewed = tic ();
endfunction

function link = read_truth (link)
  % Keeps the newest GroundTruth queued; renews the subscription every second (lease 5 s).
  if (toc (link.truth_renewed) > 1)
    link = subscribe_truth (link);
  endif
  while (true)
    bytes = lfup_receive (link.truth, 0);
    if (isempty (bytes))
      break;
    endif
    [truth, reason] = lfup_decode_truth (bytes);
    if (isempty (reason) && (isempty (link.truth_latest)
                             || truth.sequence > link.truth_latest.sequence))
      link.truth_latest = truth;
    endif
  endwhile
endfunction

function [link, reply] = control_request (link, op, varargin)
  % Up to 3 tries of 300 ms with the same request id; errors unless the result is ok.
  link.request_id = mod (link.request_id + 1, 2^32);
  for attempt = 1:3
    link = send (link, "control", lfup_encode_control_request (link.sequence.control,
                                                               link.request_id, op,
                                                               varargin{:}));
    link.sequence.control += 1;
    sent = tic ();
    while (toc (sent) < 0.3)
      bytes = lfup_receive (link.control, 0.3 - toc (sent));
      if (isempty (bytes))
        continue;
      endif
      [reply, reason] = lfup_decode_control_reply (bytes);
      if (isempty (reason) && reply.request_id == link.request_id)
        if (reply.result != 0)
          error ("drive_square: control op %d refused: %s", op, reply.message);
        endif
        return;
      endif
    endwhile
  endfor
  error ("drive_square: no reply from the simulator at %s:%d — is legofeup-sim running?",
         link.host, link.ports.control);
endfunction

% --- odometry and control ------------------------------------------------------------------

function [pose, counts, travelled] = odometry (pose, counts, new_counts)
  % Eq. 7-9 with the nominal robot: wheel 1 is the right one, 1 count = 1 degree.
  metres_per_count = pi * 0.0432 / 360;
  wheel_base = 0.12;
  delta = mod (new_counts - counts + 2^31, 2^32) - 2^31;   % int32 counters may wrap
  counts = new_counts;
  d1 = delta(1) * metres_per_count;
  d2 = delta(2) * metres_per_count;
  d = (d1 + d2) / 2;
  dtheta = (d1 - d2) / wheel_base;
  heading = pose(3) + dtheta / 2;
  pose = [pose(1) + d * cos(heading), pose(2) + d * sin(heading), wrap(pose(3) + dtheta)];
  travelled = abs (d);
endfunction

function a = wrap (a)
  a = mod (a + pi, 2 * pi) - pi;
endfunction

function legs = square_legs (laps)
  % Turn to each side, drive along it; four sides a lap; a last turn to face +x again.
  legs = struct ("kind", {}, "side", {});
  for lap = 1:laps
    for side = 1:4
      legs(end + 1) = struct ("kind", "turn", "side", side);
      legs(end + 1) = struct ("kind", "drive", "side", side);
    endfor
  endfor
  legs(end + 1) = struct ("kind", "turn", "side", 1);
endfunction

function [a, b] = side_ends (side)
  corners = [1, -1; 1, 1; -1, 1; -1, -1];            % counter-clockwise from the start
  a = corners(mod (side - 2, 4) + 1, :);
  b = corners(side, :);
endfunction

function [command, leg] = square_step (legs, leg, pose)
  % (V, W) for the current leg; a finished leg hands over to the next at once.
  v_ref = 0.1; w_ref = 0.8;                          % m/s, rad/s
  command = [0, 0];
  while (leg <= numel (legs))
    [a, b] = side_ends (legs(leg).side);
    u = (b - a) / norm (b - a);
    if (strcmp (legs(leg).kind, "turn"))
      err = wrap (atan2 (u(2), u(1)) - pose(3));
      if (abs (err) >= 0.01)                         % rad: done within 0.6 degrees
        command = [0, sign(err) * min(w_ref, max(0.1, 2 * abs(err)))];
        return;
      endif
    else
      remaining = (b - pose(1:2)) * u.';             % along the side, to its corner
      if (remaining > 0)
        % Aim at the side 0.2 m ahead of the robot's projection on it.
        cross_track = u(1) * (pose(2) - a(2)) - u(2) * (pose(1) - a(1));
        err = wrap (atan2 (u(2), u(1)) - atan2 (cross_track, 0.2) - pose(3));
        w = max (-w_ref, min (w_ref, 2 * err));
        % Slow down over the last 0.1 m (1/s times the distance left, at least 2 cm/s).
        v = min (v_ref * max (0, cos (err)), max (0.02, remaining));
        command = [v, w];
        return;
      endif
    endif
    leg += 1;
  endwhile
endfunction

function wheels = wheel_speeds (command)
  % Eq. 1: V1 (right) = V + b W/2, V2 (left) = V - b W/2, scaled together to stay under
  % the motors' 0.385 m/s.
  wheels = command(1) + [1, -1] * 0.12 * command(2) / 2;
  largest = max (abs (wheels));
  if (largest > 0.38)
    wheels *= 0.38 / largest;
  endif
endfunction

% --- output --------------------------------------------------------------------------------

function print_readings (frame, pose)
  distances = lfup_ir_distance (frame.ir_adc, frame.ir_valid);
  printf ("t=%7.2f s  counts R=%6d L=%6d  IR front %s  rear %s  odometry x=%+.3f y=%+.3f θ=%+7.2f°\n",
          frame.time, frame.encoders(1), frame.encoders(2),
          describe_ir (frame.ir_adc(1), frame.ir_valid(1), distances(1)),
          describe_ir (frame.ir_adc(2), frame.ir_valid(2), distances(2)),
          pose(1), pose(2), pose(3) * 180 / pi);
endfunction

function text = describe_ir (adc, valid, distance)
  if (! valid)
    text = "  - (no reading) ";
  elseif (isnan (distance))
    text = sprintf ("%4d (out of range)", adc);
  else
    text = sprintf ("%4d = %5.1f cm   ", adc, distance * 100);
  endif
endfunction

function text = format_pose (pose)
  text = sprintf ("(%.3f, %.3f, %.3f)", pose(1), pose(2), pose(3));
endfunction
