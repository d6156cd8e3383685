# The panels' parts.
legofeup_add_ui_gtest(ui_panels_test test_number_text.cpp)
