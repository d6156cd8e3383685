# The session, its worker and its history.
legofeup_add_ui_gtest(ui_live_run_test test_live_run.cpp)
if(LEGOFEUP_WITH_NXT)
    target_sources(ui_live_run_test PRIVATE test_live_run_on_nxt.cpp)  # an emulated brick
endif()
legofeup_add_ui_gtest(ui_run_history_test test_run_history.cpp)
legofeup_add_ui_gtest(ui_run_recorder_test test_run_recorder.cpp)
legofeup_add_ui_gtest(ui_refilter_job_test test_refilter_job.cpp)
