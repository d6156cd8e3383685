# The session and its worker.
legofeup_add_ui_gtest(ui_live_run_test test_live_run.cpp)
