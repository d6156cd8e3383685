#include "legofeup/ui/panels/config_panel.hpp"

#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QToolBox>
#include <QVBoxLayout>
#include <array>

#include "legofeup/ui/panels/message_line.hpp"
#include "legofeup/ui/panels/setting_editor.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

struct Page {
    const char* title;
    std::vector<std::string> sections;  // config_schema sections shown on this page
};

// The order students meet them: the filter's noise first, the simulator's errors next.
const std::array<Page, 6>& pages() {
    static const std::array<Page, 6> kPages = {{
        {QT_TRANSLATE_NOOP("ConfigPanel", "Filter: Q and R"), {"filter"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Initial belief: pose and P0"), {"initial"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Controller: path, V_ref, W_ref"), {"control"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Simulator: noise and systematic errors"), {"simulator"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Robot and sensors"),
         {"robot", "ir_curve", "association"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Run: seed, laps, world"), {""}},
    }};
    return kPages;
}

/// The length of the paper's symbol at the start of a help text ("Q11: variance of …",
/// "V_ref: reference speed"), or 0 when the help starts otherwise ("false: odometry only").
std::size_t symbol_length(const std::string& help) {
    const std::size_t colon = help.find(':');
    if (colon == std::string::npos || colon == 0 || colon > 6) {
        return 0;
    }
    const std::string symbol = help.substr(0, colon);
    const bool symbol_like = symbol.find(' ') == std::string::npos && symbol != "false"
                             && symbol != "true" && symbol != "0" && symbol != "line"
                             && symbol != "circle" && symbol != "goto";
    return symbol_like ? colon : 0;
}

/// "Q11" from "Q11: variance of …"; otherwise the key's name in words.
QString short_label(const lessons::Setting& setting) {
    if (const std::size_t length = symbol_length(setting.help); length > 0) {
        const std::string symbol = setting.help.substr(0, length);
        // The three P0 entries differ by their variable: "P0 x", "P0 y", "P0 theta".
        return QString::fromStdString(symbol == "P0" ? "P0 " + setting.name().substr(4) : symbol);
    }
    QString name = QString::fromStdString(setting.name());
    name.replace('_', ' ');
    return name;
}

QString help_text(const lessons::Setting& setting) {
    const std::size_t colon = setting.help.find(':');
    std::string help =
        colon != std::string::npos && colon <= 8 ? setting.help.substr(colon + 2) : setting.help;
    QString text = QString::fromStdString(help);
    if (!applies_live(setting)) {
        text += QObject::tr(" — applies at the next start");
    }
    return text;
}

}  // namespace

ConfigPanel::ConfigPanel(Session& session, QWidget* parent) : QWidget(parent), session_(session) {
    auto* layout = new QVBoxLayout(this);
    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("configMessage"));
    message_->setWordWrap(true);
    message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    message_->setText(tr("Type a value and press Enter; it applies at once."));
    layout->addWidget(message_);

    pages_ = new QToolBox(this);
    layout->addWidget(pages_, 1);
    for (const Page& page : pages()) {
        auto* form_widget = new QWidget;
        auto* form = new QFormLayout(form_widget);
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        for (const lessons::Setting& setting : lessons::run_settings()) {
            if (std::find(page.sections.begin(), page.sections.end(), setting.section())
                == page.sections.end()) {
                continue;
            }
            auto* editor = new SettingEditor(setting, form_widget);
            editors_[setting.key] = editor;
            auto* help = new QLabel(help_text(setting), form_widget);
            help->setWordWrap(true);
            help->setForegroundRole(QPalette::PlaceholderText);
            auto* field = new QWidget(form_widget);
            auto* field_layout = new QVBoxLayout(field);
            field_layout->setContentsMargins(0, 0, 0, 4);
            field_layout->setSpacing(0);
            field_layout->addWidget(editor);
            field_layout->addWidget(help);
            form->addRow(short_label(setting), field);
            connect(
                editor, &SettingEditor::proposed, this,
                [this, editor](const lessons::SettingValue& value, const QString& text) {
                    const QString refused = session_.changeSetting(editor->setting(), value);
                    if (refused.isEmpty()) {
                        showMessage(tr("%1 = %2 %3")
                                        .arg(QString::fromStdString(editor->setting().key), text,
                                             applies_live(editor->setting())
                                                 ? tr("applied")
                                                 : tr("set: applies at the next start")),
                                    false);
                    } else {
                        editor->showValueOf(session_.config());
                        showMessage(
                            tr("Refused %1 = %2:\n%3")
                                .arg(QString::fromStdString(editor->setting().key), text, refused),
                            true);
                    }
                });
            connect(editor, &SettingEditor::unreadable, this,
                    [this, editor](const QString& text, const QString& reason) {
                        editor->showValueOf(session_.config());
                        showMessage(
                            tr("Refused %1 = \"%2\": %3; the value stays %4")
                                .arg(QString::fromStdString(editor->setting().key), text, reason,
                                     QString::fromStdString(lessons::format_setting_value(
                                         editor->setting().get(session_.config())))),
                            true);
                    });
        }
        auto* scroll = new QScrollArea;
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(form_widget);
        pages_->addItem(scroll, tr(page.title));
    }
    connect(&session_, &Session::configChanged, this, &ConfigPanel::refresh);
    refresh();
}

SettingEditor* ConfigPanel::editor(const std::string& key) const {
    const auto found = editors_.find(key);
    return found == editors_.end() ? nullptr : found->second;
}

QString ConfigPanel::message() const {
    return message_->text();
}

void ConfigPanel::refresh() {
    for (const auto& [key, editor] : editors_) {
        editor->showValueOf(session_.config());
    }
}

void ConfigPanel::showMessage(const QString& text, bool error) {
    message_is_error_ = error;
    show_message_line(*message_, text, error);
}

}  // namespace legofeup::ui
