#pragma once
// A line of feedback under a form (what was applied, or why an entry was refused): its text,
// in red when it reports a refusal, in the palette's text colour otherwise.

#include <QString>

class QLabel;

namespace legofeup::ui {

void show_message_line(QLabel& label, const QString& text, bool error);

}  // namespace legofeup::ui
