// Plot frame-time benchmarks (filled in with the plots).
