#pragma once
// The File menu's lesson entries: Open lesson…, Save answers…, Open answers…, Export
// report…. Each asks for a path, has the lesson panel do the work, and says what it wrote or,
// in a message box, why not (a lesson or answers file with errors: every problem with its
// file:line).

#include <QObject>

class QWidget;

namespace legofeup::ui {

class LessonPanel;

class LessonActions : public QObject {
    Q_OBJECT

  public:
    LessonActions(LessonPanel& panel, QWidget* dialog_parent);

  public slots:
    void openLesson();
    void saveAnswers();
    void openAnswers();
    void exportReport();

  signals:
    /// A short note of what was done, for the status bar.
    void done(const QString& note);

  private:
    QString folder() const;
    void remember(const QString& path) const;
    void warn(const QString& title, const QString& error);

    LessonPanel& panel_;
    QWidget* dialog_parent_;
};

}  // namespace legofeup::ui
