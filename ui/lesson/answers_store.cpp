#include "legofeup/ui/lesson/answers_store.hpp"

#include <QSettings>
#include <QVariantMap>

namespace legofeup::ui {
namespace {

// One map per lesson: "students" and "<step>/<question>" → text.
QString key_of(const LessonProgress& progress) {
    return QStringLiteral("answers/") + QString::fromStdString(progress.lesson().id);
}

const QString kStudents = QStringLiteral("students");

}  // namespace

void store_answers(const LessonProgress& progress) {
    QVariantMap kept;
    kept[kStudents] = QString::fromStdString(progress.students());
    for (const auto& [step, answers] : progress.answers()) {
        for (const auto& [question, text] : answers) {
            kept[QString::fromStdString(step + "/" + question)] = QString::fromStdString(text);
        }
    }
    QSettings().setValue(key_of(progress), kept);
}

void restore_answers(LessonProgress& progress) {
    const QVariantMap kept = QSettings().value(key_of(progress)).toMap();
    Answers answers;
    for (auto entry = kept.constBegin(); entry != kept.constEnd(); ++entry) {
        const qsizetype slash = entry.key().indexOf('/');
        if (slash > 0) {
            answers[entry.key().left(slash).toStdString()]
                   [entry.key().mid(slash + 1).toStdString()] =
                       entry.value().toString().toStdString();
        }
    }
    progress.takeAnswers(kept.value(kStudents).toString().toStdString(), answers);
}

}  // namespace legofeup::ui
