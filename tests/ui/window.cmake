# The whole window, driven offscreen.
legofeup_add_ui_test(ui_main_window_test test_main_window.cpp)
