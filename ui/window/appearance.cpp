#include "legofeup/ui/window/appearance.hpp"

#include <QApplication>
#include <QFont>
#include <QPalette>
#include <QStyle>
#include <QStyleFactory>

namespace legofeup::ui {
namespace {

QPalette dark_palette() {
    QPalette p;
    const QColor window(0x2b, 0x2d, 0x31);
    const QColor base(0x1e, 0x1f, 0x22);
    const QColor text(0xe8, 0xe8, 0xe8);
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, window);
    p.setColor(QPalette::ToolTipBase, base);
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::PlaceholderText, QColor(0xa0, 0xa4, 0xaa));
    p.setColor(QPalette::Button, window);
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, Qt::red);
    p.setColor(QPalette::Highlight, QColor(0x3d, 0x7e, 0xd6));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::Link, QColor(0x6c, 0xa8, 0xf0));
    p.setColor(QPalette::Mid, QColor(0x45, 0x48, 0x4d));
    p.setColor(QPalette::Dark, QColor(0x18, 0x19, 0x1b));
    p.setColor(QPalette::Disabled, QPalette::Text, QColor(0x80, 0x80, 0x80));
    p.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(0x80, 0x80, 0x80));
    p.setColor(QPalette::Disabled, QPalette::WindowText, QColor(0x80, 0x80, 0x80));
    return p;
}

}  // namespace

Theme theme_from_name(const QString& name) {
    if (name == QLatin1String("dark")) {
        return Theme::Dark;
    }
    if (name == QLatin1String("light")) {
        return Theme::Light;
    }
    return Theme::System;
}

QString theme_name(Theme theme) {
    switch (theme) {
        case Theme::Dark:
            return QStringLiteral("dark");
        case Theme::Light:
            return QStringLiteral("light");
        case Theme::System:
            break;
    }
    return QStringLiteral("system");
}

void apply_appearance(QApplication& app, Theme theme, double text_scale) {
    static const QString system_style = app.style()->name();
    static const QPalette system_palette = QApplication::palette();
    static const QFont system_font = QApplication::font();
    if (theme == Theme::System) {
        QApplication::setStyle(QStyleFactory::create(system_style));
        QApplication::setPalette(system_palette);
    } else {
        QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
        QApplication::setPalette(theme == Theme::Dark ? dark_palette()
                                                      : QApplication::style()->standardPalette());
    }
    QFont font = system_font;
    font.setPointSizeF(system_font.pointSizeF() * text_scale);
    QApplication::setFont(font);
}

}  // namespace legofeup::ui
