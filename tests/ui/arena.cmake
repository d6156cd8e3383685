# arena tests: the ellipse and geometry helpers (GoogleTest) and the view itself (QtTest).
legofeup_add_ui_gtest(test_arena_ellipse test_arena_ellipse.cpp)
legofeup_add_ui_gtest(test_arena_geometry test_arena_geometry.cpp)
legofeup_add_ui_test(test_arena_view test_arena_view.cpp)
legofeup_add_ui_gtest(test_lesson_geometry test_lesson_geometry.cpp)
