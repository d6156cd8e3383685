#include "legofeup/ui/panels/message_line.hpp"

#include <QLabel>
#include <QPalette>

namespace legofeup::ui {

void show_message_line(QLabel& label, const QString& text, bool error) {
    label.setText(text);
    QPalette palette = label.palette();
    const QColor normal = label.parentWidget() != nullptr
                              ? label.parentWidget()->palette().color(QPalette::WindowText)
                              : QPalette().color(QPalette::WindowText);
    palette.setColor(QPalette::WindowText, error ? QColor(0xd0, 0x30, 0x30) : normal);
    label.setPalette(palette);
}

}  // namespace legofeup::ui
