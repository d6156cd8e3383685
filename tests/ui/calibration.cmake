# The calibration dialogs: the same numbers as the library, bad entries refused, profiles saved.
legofeup_add_ui_test(ui_calibration_dialogs_test test_calibration_dialogs.cpp)
