#include "legofeup/ui/panels/config_panel.hpp"

#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QToolBox>
#include <QVBoxLayout>
#include <algorithm>
#include <vector>

#include "legofeup/ui/panels/message_line.hpp"
#include "legofeup/ui/panels/setting_editor.hpp"
#include "legofeup/ui/panels/setting_relevance.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

struct Page {
    const char* title;
    std::vector<std::string> sections;  // config_schema sections shown on this page
};

// The order students meet them: the filter's noise first, the simulator's errors next.
const std::vector<Page>& known_pages() {
    static const std::vector<Page> kPages = {{
        {QT_TRANSLATE_NOOP("ConfigPanel", "Filter: Q and R, EKF or UKF"), {"filter"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Localisation and the lessons' filters"),
         {"localisation", "beacons", "gyro_fusion", "compass", "wheel_speed_kf", "velocity_kf",
          "calibration"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Laser: scan matching, kidnapping recovery"), {"laser"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Initial belief: pose and P0"), {"initial"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Controller: path, V_ref, W_ref"), {"control"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Simulator: noise and systematic errors"), {"simulator"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Simulator: beacons, gyro, accelerometers, compass"),
         {"beacon_scanner", "gyro", "accelerometers", "compass_sensor", "displacement"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Simulator: laser rangefinder, kidnapping"),
         {"laser_scanner", "kidnap"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Robot and sensors"),
         {"robot", "ir_mount", "ir_curve", "association"}},
        {QT_TRANSLATE_NOOP("ConfigPanel", "Run: seed, laps, world"), {""}},
    }};
    return kPages;
}

bool on_page(const Page& page, const std::string& section) {
    return std::find(page.sections.begin(), page.sections.end(), section) != page.sections.end();
}

/// The known pages that have a setting, and a last page for any section they do not name.
std::vector<Page> pages() {
    std::vector<Page> result;
    for (const Page& page : known_pages()) {
        const auto has_setting = [&page](const lessons::Setting& setting) {
            return on_page(page, setting.section());
        };
        if (std::any_of(lessons::run_settings().begin(), lessons::run_settings().end(),
                        has_setting)) {
            result.push_back(page);
        }
    }
    Page others{QT_TRANSLATE_NOOP("ConfigPanel", "Other settings"), {}};
    for (const lessons::Setting& setting : lessons::run_settings()) {
        const std::string section = setting.section();
        const auto known = [&section](const Page& page) { return on_page(page, section); };
        if (std::none_of(result.begin(), result.end(), known) && !known(others)) {
            others.sections.push_back(section);
        }
    }
    if (!others.sections.empty()) {
        result.push_back(others);
    }
    return result;
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
        const int page_index = pages_->count();
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
            rows_[setting.key] = {form->labelForField(field), field, page_index};
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
    showRelevance(session_.resolved().loop.lesson.localisation);
}

bool ConfigPanel::isRelevant(const std::string& key) const {
    const auto found = rows_.find(key);
    return found != rows_.end() && found->second.field->isEnabled();
}

void ConfigPanel::showRelevance(Localisation localisation) {
    std::vector<bool> page_used(static_cast<std::size_t>(pages_->count()), false);
    for (const auto& [key, row] : rows_) {
        const bool relevant = setting_relevant(key, localisation);
        row.field->setEnabled(relevant);
        if (row.label != nullptr) {
            row.label->setEnabled(relevant);
            row.label->setToolTip(relevant ? QString()
                                           : tr("Not used by this run: a setting of %1")
                                                 .arg(QString::fromStdString(setting_lesson(key))));
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
