# arena tests: the ellipse and geometry helpers and the view's parts (GoogleTest), the view
# itself and its layers (QtTest).
legofeup_add_ui_gtest(test_arena_ellipse test_arena_ellipse.cpp)
legofeup_add_ui_gtest(test_arena_geometry test_arena_geometry.cpp)
legofeup_add_ui_gtest(test_arena_parts test_arena_parts.cpp)
legofeup_add_ui_test(test_arena_layers test_arena_layers.cpp)
legofeup_add_ui_test(test_arena_view test_arena_view.cpp)
legofeup_add_ui_gtest(test_lesson_geometry test_lesson_geometry.cpp)
