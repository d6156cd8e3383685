#include "legofeup/ui/panels/setting_editor.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSignalBlocker>
#include <cmath>

#include "legofeup/ui/panels/log_slider.hpp"
#include "legofeup/ui/panels/number_text.hpp"

namespace legofeup::ui {
namespace {

// The decade span of the variance sliders: the experiments' "very low" (1e-12) to "very
// high" (1e-1) with room on both sides. Typed values may go beyond (1e-15 … 1e9).
constexpr int kSliderMinDecade = -14;
constexpr int kSliderMaxDecade = 4;

}  // namespace

QString setting_text(const char* source) {
    return QCoreApplication::translate(lessons::kSettingTextContext, source);
}

bool SettingEditor::isVariance(const lessons::Setting& setting) {
    const std::string name = setting.name();
    return setting.type == lessons::SettingType::Real
           && (setting.key.starts_with("filter.q") || setting.key.starts_with("filter.r")
               || name.starts_with("var_"));
}

SettingEditor::SettingEditor(const lessons::Setting& setting, QWidget* parent)
    : QWidget(parent), setting_(setting) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    setToolTip(QString::fromStdString(setting.key) + '\n' + setting_text(setting.help.c_str()));
    switch (setting.type) {
        case lessons::SettingType::Real:
            buildNumber(false);
            break;
        case lessons::SettingType::Integer:
            buildNumber(true);
            break;
        case lessons::SettingType::Boolean:
            buildBoolean();
            break;
        case lessons::SettingType::Choice:
            buildChoice();
            break;
        case lessons::SettingType::Point:
            buildPoint();
            break;
        case lessons::SettingType::Text:
            buildText();
            break;
    }
}

void SettingEditor::buildNumber(bool integer) {
    auto* field = new QLineEdit(this);
    field->setObjectName(QString::fromStdString(setting_.key));
    field->setAccessibleName(setting_text(setting_.help.c_str()));
    fields_ << field;
    if (isVariance(setting_)) {
        slider_ = new LogSlider(kSliderMinDecade, kSliderMaxDecade, this);
        slider_->setObjectName(QString::fromStdString(setting_.key + ".slider"));
        slider_->setToolTip(tr("Drag across decades; type the exact value on the right"));
        layout()->addWidget(slider_);
        connect(slider_, &LogSlider::valueProposed, this, [this](double value) {
            emit proposed(lessons::SettingValue(value), number_text(value));
        });
        field->setMaximumWidth(fontMetrics().horizontalAdvance(QStringLiteral("0.0000000001")));
    }
    layout()->addWidget(field);
    connect(field, &QLineEdit::editingFinished, this,
            [this, field, integer] { numberEntered(field, integer); });
}

void SettingEditor::numberEntered(QLineEdit* field, bool integer) {
    if (!field->isModified()) {
        return;  // focus left without an edit
    }
    field->setModified(false);
    const QString text = field->text();
    const std::optional<double> number = parse_number(text);
    if (!number) {
        emit unreadable(text, tr("not a number"));
        return;
    }
    if (integer) {
        if (*number != std::floor(*number) || std::abs(*number) > 9.0e15) {
            emit unreadable(text, tr("not a whole number"));
            return;
        }
        emit proposed(lessons::SettingValue(static_cast<std::int64_t>(*number)), text);
        return;
    }
    emit proposed(lessons::SettingValue(*number), text);
}

void SettingEditor::buildPoint() {
    for (const char* axis : {"x", "y"}) {
        auto* field = new QLineEdit(this);
        field->setObjectName(QString::fromStdString(setting_.key + "." + axis));
        field->setPlaceholderText(QString::fromLatin1(axis));
        fields_ << field;
        layout()->addWidget(field);
        connect(field, &QLineEdit::editingFinished, this, [this, field] {
            if (!field->isModified()) {
                return;
            }
            field->setModified(false);
            const std::optional<double> x = parse_number(fields_[0]->text());
            const std::optional<double> y = parse_number(fields_[1]->text());
            const QString text = fields_[0]->text() + ", " + fields_[1]->text();
            if (!x || !y) {
                emit unreadable(text, tr("not a point: two numbers x, y"));
                return;
            }
            emit proposed(lessons::SettingValue(Vector2(*x, *y)), text);
        });
    }
}

void SettingEditor::buildText() {
    auto* field = new QLineEdit(this);
    field->setObjectName(QString::fromStdString(setting_.key));
    fields_ << field;
    layout()->addWidget(field);
    connect(field, &QLineEdit::editingFinished, this, [this, field] {
        if (field->isModified()) {
            field->setModified(false);
            emit proposed(lessons::SettingValue(field->text().toStdString()), field->text());
        }
    });
}

void SettingEditor::buildBoolean() {
    auto* box = new QCheckBox(this);
    box->setObjectName(QString::fromStdString(setting_.key));
    layout()->addWidget(box);
    connect(box, &QCheckBox::clicked, this, [this](bool checked) {
        emit proposed(lessons::SettingValue(checked),
                      checked ? QStringLiteral("true") : QStringLiteral("false"));
    });
}

void SettingEditor::buildChoice() {
    auto* box = new QComboBox(this);
    box->setObjectName(QString::fromStdString(setting_.key));
    for (const std::string& choice : setting_.choices) {
        box->addItem(QString::fromStdString(choice));
    }
    layout()->addWidget(box);
    connect(box, &QComboBox::activated, this, [this, box](int index) {
        const QString text = box->itemText(index);
        emit proposed(lessons::SettingValue(text.toStdString()), text);
    });
}

void SettingEditor::showValueOf(const lessons::RunConfig& config) {
    const lessons::SettingValue value = setting_.get(config);
    const bool unset = setting_.is_set && !setting_.is_set(config);
    if (const auto* number = std::get_if<double>(&value)) {
        fields_[0]->setText(unset ? QString() : number_text(*number));
        fields_[0]->setPlaceholderText(unset ? tr("world's start") : QString());
        if (slider_ != nullptr) {
            slider_->showValue(*number);
        }
    } else if (const auto* integer = std::get_if<std::int64_t>(&value)) {
        fields_[0]->setText(QString::number(*integer));
    } else if (const auto* flag = std::get_if<bool>(&value)) {
        auto* box = findChild<QCheckBox*>();
        const QSignalBlocker blocker(box);
        box->setChecked(*flag);
    } else if (const auto* text = std::get_if<std::string>(&value)) {
        if (auto* box = findChild<QComboBox*>()) {
            const QSignalBlocker blocker(box);
            box->setCurrentText(QString::fromStdString(*text));
        } else {
            fields_[0]->setText(QString::fromStdString(*text));
        }
    } else if (const auto* point = std::get_if<Vector2>(&value)) {
        fields_[0]->setText(number_text(point->x()));
        fields_[1]->setText(number_text(point->y()));
    }
    for (QLineEdit* field : fields_) {
        field->setModified(false);
    }
}

}  // namespace legofeup::ui
