// Arena view frame-time benchmarks (filled in with the arena view).
