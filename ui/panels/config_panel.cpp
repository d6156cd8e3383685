#include "legofeup/ui/panels/config_panel.hpp"

#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QToolBox>
#include <QVBoxLayout>
#include <vector>

#include "legofeup/ui/panels/message_line.hpp"
#include "legofeup/ui/panels/setting_editor.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

/// The help under a row: the table's, and when it waits for the next start, that it does.
QString help_text(const lessons::Setting& setting) {
    QString text = setting_text(setting.help.c_str());
    if (!setting.applies_live()) {
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
    for (const lessons::SettingPage page : lessons::setting_pages()) {
        const int page_index = pages_->count();
        auto* form_widget = new QWidget;
        auto* form = new QFormLayout(form_widget);
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        for (const lessons::Setting& setting : lessons::run_settings()) {
            if (setting.page != page) {
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
            form->addRow(setting_text(setting.label.text), field);
            rows_[setting.key] = {&setting, form->labelForField(field), field, page_index};
            connect(
                editor, &SettingEditor::proposed, this,
                [this, editor](const lessons::SettingValue& value, const QString& text) {
                    const QString refused = session_.changeSetting(editor->setting(), value);
                    if (refused.isEmpty()) {
                        showMessage(tr("%1 = %2 %3")
                                        .arg(QString::fromStdString(editor->setting().key), text,
                                             editor->setting().applies_live()
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
        pages_->addItem(scroll, setting_text(lessons::setting_page_title(page)));
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
    showRelevance(session_.config());
}

bool ConfigPanel::isRelevant(const std::string& key) const {
    const auto found = rows_.find(key);
    return found != rows_.end() && found->second.field->isEnabled();
}

void ConfigPanel::showRelevance(const lessons::RunConfig& config) {
    std::vector<bool> page_used(static_cast<std::size_t>(pages_->count()), false);
    for (const auto& [key, row] : rows_) {
        const bool relevant = row.setting->used_by(config);
        row.field->setEnabled(relevant);
        if (row.label != nullptr) {
            row.label->setEnabled(relevant);
            row.label->setToolTip(relevant ? QString()
                                           : tr("Not used by this run: a setting of %1")
                                                 .arg(setting_text(row.setting->use.runs)));
        }
        if (relevant) {
            page_used[static_cast<std::size_t>(row.page)] = true;
        }
    }
    // A page none of whose settings this run uses is greyed (it still opens on a click
    // of an enabled page only), so the lesson's own pages stand out.
    for (int page = 0; page < pages_->count(); ++page) {
        pages_->setItemEnabled(page, page_used[static_cast<std::size_t>(page)]);
    }
}

void ConfigPanel::showMessage(const QString& text, bool error) {
    message_is_error_ = error;
    show_message_line(*message_, text, error);
}

}  // namespace legofeup::ui
