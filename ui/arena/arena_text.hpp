#pragma once
// The arena's texts (private to ui/arena): translated in the "ArenaView" context, whichever
// of its classes draws them, and the filters' names as the legend and the labels give them.
#include <QCoreApplication>
#include <QString>

#include "legofeup/core/lesson_filters_config.hpp"

namespace legofeup::ui::arena_text {

inline QString tr(const char* text) {
    return QCoreApplication::translate("ArenaView", text);
}

inline QString kind_text(FilterKind kind) {
    switch (kind) {
        case FilterKind::Ekf:
            return QStringLiteral("EKF");
        case FilterKind::Ukf:
            return QStringLiteral("UKF");
        case FilterKind::Pf:
            return QStringLiteral("PF");
    }
    return QStringLiteral("EKF");
}

/// What the primary estimate is, for the legend: "EKF", "UKF", "PF" or "5-state EKF".
inline QString estimator_text(Localisation localisation, FilterKind kind) {
    return localisation == Localisation::GyroFusion ? QStringLiteral("5-state EKF")
                                                    : kind_text(kind);
}

}  // namespace legofeup::ui::arena_text
