# The session: owns the run (its link and loop on a worker thread) and its history.
list(APPEND LEGOFEUP_UI_SOURCES
    session/live_run.cpp
    session/session.cpp
    session/run_history.cpp
    session/run_recorder.cpp
    session/run_samples.cpp
    include/legofeup/ui/session/session.hpp  # Q_OBJECT: listed for AUTOMOC
)
# How a run takes an NXT (nxt_connection.hpp): its address as typed, the brick, real or
# emulated; in a build without the NXT (LEGOFEUP_WITH_NXT=OFF), the file that has none.
if(LEGOFEUP_WITH_NXT)
    list(APPEND LEGOFEUP_UI_SOURCES session/nxt_address.cpp session/nxt_connection.cpp)
else()
    list(APPEND LEGOFEUP_UI_SOURCES session/no_nxt_connection.cpp)
endif()
