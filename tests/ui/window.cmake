# The whole window, driven offscreen.
legofeup_add_ui_test(ui_main_window_test test_main_window.cpp)
# The NXT connect dialog: address checks, recent robots, a scan without BlueZ.
legofeup_add_ui_test(ui_connect_dialog_test test_connect_dialog.cpp)
# The real-robot path in the window: the emulated brick, the link's status, reconnecting.
legofeup_add_ui_test(ui_nxt_window_test test_nxt_window.cpp)
