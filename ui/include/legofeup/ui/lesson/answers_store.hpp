#pragma once
// The students' names and answers kept with the preferences as they type, one set per lesson
// id, so a crash, a closed window or a restart never loses them (File ▸ Save answers… writes
// the file to hand in; this is the safety net).

#include "legofeup/ui/lesson/lesson_progress.hpp"

namespace legofeup::ui {

/// Keeps the names and answers of `progress` under its lesson's id.
void store_answers(const LessonProgress& progress);
/// Takes the names and answers kept for `progress`'s lesson (if any).
void restore_answers(LessonProgress& progress);

}  // namespace legofeup::ui
