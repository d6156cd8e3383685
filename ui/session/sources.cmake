# The session: owns the run (its link and loop on a worker thread) and its history.
list(APPEND LEGOFEUP_UI_SOURCES
    session/live_run.cpp
    session/nxt_address.cpp
    session/session.cpp
    session/run_history.cpp
    session/run_recorder.cpp
    session/run_samples.cpp
    include/legofeup/ui/session/session.hpp  # Q_OBJECT: listed for AUTOMOC
)
