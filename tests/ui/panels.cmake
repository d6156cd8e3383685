# The panels' parts.
legofeup_add_ui_gtest(ui_panels_test test_covariance_view.cpp test_number_text.cpp)
