# The lesson dock: the lesson and its steps, the selected step's texts, answers, checks and
# conclusion, which step a run belongs to, the answers kept as typed, the File menu's entries.
list(APPEND LEGOFEUP_UI_SOURCES
    lesson/answers_store.cpp
    lesson/lesson_actions.cpp
    lesson/lesson_panel.cpp
    lesson/lesson_progress.cpp
    lesson/shown_run.cpp
    lesson/step_membership.cpp
    lesson/step_run_tracker.cpp
    lesson/step_view.cpp
    include/legofeup/ui/lesson/lesson_actions.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/lesson/lesson_panel.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/lesson/step_run_tracker.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/lesson/step_view.hpp  # Q_OBJECT: listed for AUTOMOC
)
