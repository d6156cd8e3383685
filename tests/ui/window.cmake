# The whole window, driven offscreen.
legofeup_add_ui_test(ui_main_window_test test_main_window.cpp)
if(LEGOFEUP_WITH_NXT)
    # The NXT connect dialog: address checks, recent robots, a scan without BlueZ.
    legofeup_add_ui_test(ui_connect_dialog_test test_connect_dialog.cpp)
    # The real-robot path in the window: the emulated brick, the link's status, reconnecting.
    legofeup_add_ui_test(ui_nxt_window_test test_nxt_window.cpp)
else()
    # A build without the NXT: the window offers none, and an NXT chosen anyway is refused.
    legofeup_add_ui_test(ui_no_nxt_window_test test_no_nxt_window.cpp)
endif()
# legofeup's command line (read before any window) and the window it starts.
legofeup_add_ui_gtest(ui_command_line_test test_command_line.cpp)
legofeup_add_ui_test(ui_start_up_test test_start_up.cpp)
# --screenshot-at's moment: the run time reached, or the run's end.
legofeup_add_ui_test(ui_at_run_time_test test_at_run_time.cpp)
