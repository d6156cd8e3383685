#include "legofeup/ui/panels/experiment_panel.hpp"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {

ExperimentPanel::ExperimentPanel(Session& session, QWidget* parent)
    : QWidget(parent), session_(session) {
    auto* layout = new QVBoxLayout(this);
    choice_ = new QComboBox(this);
    choice_->setObjectName(QStringLiteral("experimentChoice"));
    for (const lessons::Experiment& experiment : lessons::legofeup_experiments()) {
        choice_->addItem(QStringLiteral("%1) %2").arg(QString::fromStdString(experiment.id),
                                                      QString::fromStdString(experiment.title)),
                         QString::fromStdString(experiment.id));
    }
    layout->addWidget(choice_);

    text_ = new QTextBrowser(this);
    text_->setObjectName(QStringLiteral("experimentInstructions"));
    text_->setOpenLinks(false);
    layout->addWidget(text_, 1);

    reveal_ = new QPushButton(tr("Show the expected conclusion"), this);
    reveal_->setCheckable(true);
    layout->addWidget(reveal_);
    expectation_ = new QLabel(this);
    expectation_->setObjectName(QStringLiteral("experimentExpectation"));
    expectation_->setWordWrap(true);
    expectation_->setVisible(false);
    layout->addWidget(expectation_);
    connect(reveal_, &QPushButton::toggled, this, [this](bool shown) {
        expectation_->setVisible(shown);
        reveal_->setText(shown ? tr("Hide the expected conclusion")
                               : tr("Show the expected conclusion"));
    });

    note_ = new QLabel(this);
    note_->setWordWrap(true);
    layout->addWidget(note_);

    connect(choice_, &QComboBox::activated, this, &ExperimentPanel::apply);
    showExperiment(QStringLiteral("f"));
}

bool ExperimentPanel::selectExperiment(const QString& id) {
    const int index = choice_->findData(id);
    if (index < 0) {
        return false;
    }
    choice_->setCurrentIndex(index);
    apply(index);
    return true;
}

void ExperimentPanel::showExperiment(const QString& id) {
    const int index = choice_->findData(id);
    const lessons::Experiment* experiment = lessons::find_experiment(id.toStdString());
    if (index < 0 || experiment == nullptr) {
        return;
    }
    choice_->setCurrentIndex(index);
    text_->setPlainText(QString::fromStdString(experiment->instructions));
    expectation_->setText(QString::fromStdString(experiment->expectation));
    reveal_->setChecked(false);  // a new step's conclusion starts folded
}

QString ExperimentPanel::currentExperiment() const {
    return choice_->currentData().toString();
}

QString ExperimentPanel::instructions() const {
    return text_->toPlainText();
}

void ExperimentPanel::apply(int index) {
    const lessons::Experiment* experiment =
        lessons::find_experiment(choice_->itemData(index).toString().toStdString());
    if (experiment == nullptr) {
        return;
    }
    showExperiment(QString::fromStdString(experiment->id));
    const QStringList problems = session_.setConfig(experiment->config);
    if (!problems.isEmpty()) {
        note_->setText(tr("The preset was refused:\n%1").arg(problems.join('\n')));
        return;
    }
    note_->setText(session_.running()
                       ? tr("Preset %1 applied: Q, R and the noise take effect now, the rest "
                            "at the next start.")
                             .arg(currentExperiment())
                       : tr("Preset %1 applied. Press Start.").arg(currentExperiment()));
    emit experimentApplied(currentExperiment());
}

}  // namespace legofeup::ui
