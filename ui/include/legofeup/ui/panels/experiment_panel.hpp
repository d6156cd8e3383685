#pragma once
// The guided experiments a–f of the lesson: picking one applies its preset to the session and
// shows what to do; its expected conclusion stays folded until the student asks for it.

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTextBrowser;

namespace legofeup::ui {

class Session;

class ExperimentPanel : public QWidget {
    Q_OBJECT

  public:
    explicit ExperimentPanel(Session& session, QWidget* parent = nullptr);

    /// Picks experiment `id` ("a" … "f") and applies its preset. False for an unknown id.
    bool selectExperiment(const QString& id);
    /// Shows experiment `id`'s text without touching the configuration (at start-up, when
    /// the configuration is the one last used).
    void showExperiment(const QString& id);
    QString currentExperiment() const;
    QString instructions() const;

  signals:
    void experimentApplied(const QString& id);

  private:
    void apply(int index);

    Session& session_;
    QComboBox* choice_ = nullptr;
    QTextBrowser* text_ = nullptr;
    QPushButton* reveal_ = nullptr;
    QLabel* expectation_ = nullptr;
    QLabel* note_ = nullptr;
};

}  // namespace legofeup::ui
