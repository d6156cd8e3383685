# The Lesson dock and what students hand in; File ▸ Re-filter recorded run and recording.
legofeup_add_ui_gtest(ui_lesson_progress_test test_lesson_progress.cpp)
legofeup_add_ui_gtest(ui_step_membership_test test_step_membership.cpp)
legofeup_add_ui_test(ui_lesson_panel_test test_lesson_panel.cpp)
legofeup_add_ui_test(ui_refilter_dialog_test test_refilter_dialog.cpp)
legofeup_add_ui_gtest(ui_shown_run_test test_shown_run.cpp)
