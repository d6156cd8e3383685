# plots tests
legofeup_add_ui_test(test_plots_panel test_plots_panel.cpp)
legofeup_add_ui_test(test_plots_export test_plots_export.cpp)
