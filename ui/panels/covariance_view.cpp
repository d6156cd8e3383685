#include "legofeup/ui/panels/covariance_view.hpp"

#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>
#include <cmath>

#include "legofeup/core/angles.hpp"
#include "legofeup/ui/arena/laser_layer.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

CovarianceView::CovarianceView(const RunHistory& history, QWidget* parent)
    : QWidget(parent), history_(history) {
    auto* grid = new QGridLayout(this);
    const std::array<QString, 3> names = {QStringLiteral("x"), QStringLiteral("y"),
                                          QStringLiteral("θ")};
    grid->addWidget(new QLabel(QStringLiteral("P"), this), 0, 0);
    for (int i = 0; i < 3; ++i) {
        grid->addWidget(new QLabel(names[static_cast<std::size_t>(i)], this), 0, i + 1,
                        Qt::AlignCenter);
        grid->addWidget(new QLabel(names[static_cast<std::size_t>(i)], this), i + 1, 0);
        for (int j = 0; j < 3; ++j) {
            auto* cell = new QLabel(this);
            cell->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
            cell->setTextInteractionFlags(Qt::TextSelectableByMouse);
            cell->setObjectName(QStringLiteral("P%1%2").arg(i).arg(j));
            cells_[static_cast<std::size_t>(i * 3 + j)] = cell;
            grid->addWidget(cell, i + 1, j + 1);
        }
    }
    sigmas_ = new QLabel(this);
    grid->addWidget(sigmas_, 4, 0, 1, 4);
    update_ = new QLabel(this);
    update_->setWordWrap(true);
    grid->addWidget(update_, 5, 0, 1, 4);
    grid->setRowStretch(6, 1);
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(2, 1);
    grid->setColumnStretch(3, 1);
    useMonospaceFont();
    showLatest();
}

void CovarianceView::useMonospaceFont() {
    // The numbers line up in a fixed-width font, as large as the rest of the text (which
    // follows the application's font: the projector's large text included).
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mono.setPointSizeF(font().pointSizeF());
    for (QLabel* label : cells_) {
        label->setFont(mono);
    }
    sigmas_->setFont(mono);
    update_->setFont(mono);
}

void CovarianceView::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) {
        useMonospaceFont();
    }
}

QString CovarianceView::cellText(int row, int column) const {
    return cells_[static_cast<std::size_t>(row * 3 + column)]->text();
}

void CovarianceView::historyRestarted() {
    showLatest();
}

void CovarianceView::samplesAppended(int /*first*/, int /*count*/) {
    showLatest();
}

void CovarianceView::showLatest() {
    if (history_.empty()) {
        for (QLabel* cell : cells_) {
            cell->setText(QStringLiteral("—"));
        }
        sigmas_->setText(tr("No run yet: press Start."));
        update_->clear();
        return;
    }
    const LoopSnapshot& snapshot = history_.latest().snapshot;
    const StateCovariance& p = snapshot.covariance;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            cells_[static_cast<std::size_t>(i * 3 + j)]->setText(QString::number(p(i, j), 'e', 3));
        }
    }
    sigmas_->setText(tr("σx %1 mm   σy %2 mm   σθ %3°")
                         .arg(1000.0 * std::sqrt(std::max(p(0, 0), 0.0)), 0, 'f', 1)
                         .arg(1000.0 * std::sqrt(std::max(p(1, 1), 0.0)), 0, 'f', 1)
                         .arg(std::sqrt(std::max(p(2, 2), 0.0)) * 180.0 / kPi, 0, 'f', 2));
    if (snapshot.localisation == Localisation::Laser) {
        showLaserUpdate();
        return;
    }
    update_->setText(wallUpdateText(snapshot, history_.scene()));
}

QString CovarianceView::updateText() const {
    return update_->text();
}

QString CovarianceView::wallUpdateText(const LoopSnapshot& snapshot, const ArenaScene& scene) {
    const WallUpdateReport& update = snapshot.update;
    const QString time = QString::number(snapshot.time, 'f', 2);
    if (update.status == StepStatus::Applied) {
        return tr("t = %1 s: wall update, innovation (%2 m, %3°), NIS %4")
            .arg(time)
            .arg(update.innovation(0), 0, 'f', 4)
            .arg(update.innovation(1) * 180.0 / kPi, 0, 'f', 2)
            .arg(update.nis, 0, 'f', 2);
    }
    const AssociationResult& a = snapshot.association;
    const auto index = static_cast<std::size_t>(a.wall);
    const QString wall = a.wall >= 0 && index < scene.walls.size()
                             ? QString::fromStdString(scene.walls[index].name)
                             : QString::number(a.wall);
    const AssociationParams& limits = scene.association;
    switch (a.outcome) {
        case AssociationOutcome::AngleMismatch:
            return tr("t = %1 s: prediction only: %2 refused by the fixed angle gate (ObsAng "
                      "error %3°, limit %4°).")
                .arg(time, wall)
                .arg(a.angle_error * 180.0 / kPi, 0, 'f', 1)
                .arg(limits.max_angle_error * 180.0 / kPi, 0, 'f', 1);
        case AssociationOutcome::DistanceMismatch:
            return tr("t = %1 s: prediction only: %2 refused by the fixed distance gate (D_c "
                      "error %3 cm, limit %4 cm; the Mahalanobis d² would be %5).")
                .arg(time, wall)
                .arg(100.0 * a.distance_error, 0, 'f', 1)
                .arg(100.0 * limits.max_distance_error, 0, 'f', 1)
                .arg(a.mahalanobis_d2, 0, 'f', 1);
        case AssociationOutcome::MahalanobisMismatch:
            return tr("t = %1 s: prediction only: %2 refused by the Mahalanobis gate (d² = %3 "
                      "above χ²(2) = %4 at p = %5).")
                .arg(time, wall)
                .arg(a.mahalanobis_d2, 0, 'f', 1)
                .arg(a.mahalanobis_threshold, 0, 'f', 2)
                .arg(limits.gate_probability, 0, 'g', 3);
        case AssociationOutcome::ObliqueIncidence:
            return tr("t = %1 s: prediction only: %2 is seen too obliquely to use.")
                .arg(time, wall);
        case AssociationOutcome::Associated:
            if (update.status == StepStatus::RejectedByGate) {
                return tr("t = %1 s: prediction only: %2 associated, but the NIS gate refused "
                          "the update (NIS %3).")
                    .arg(time, wall)
                    .arg(update.nis, 0, 'f', 1);
            }
            if (update.status == StepStatus::NotAttempted) {
                return tr("t = %1 s: prediction only: %2 associated, but wall updates are off.")
                    .arg(time, wall);
            }
            return tr("t = %1 s: prediction only: %2 associated, but the update was refused "
                      "as numerically unsafe.")
                .arg(time, wall);
        case AssociationOutcome::NoObservation:
        case AssociationOutcome::NoWallInView:
            break;
    }
    return tr("t = %1 s: prediction only (no wall update)").arg(time);
}

void CovarianceView::showLaserUpdate() {
    // Scans come every other period: the latest scan's update, at its own time.
    const RunSample* sample = latest_scan_sample(history_);
    if (sample == nullptr) {
        update_->setText(tr("t = %1 s: prediction only (no scan yet)")
                             .arg(history_.latest().snapshot.time, 0, 'f', 2));
        return;
    }
    const double time = sample->snapshot.time;
    const LaserUpdate& laser = sample->snapshot.laser;
    const ParticleSummary& particles = sample->snapshot.particles;
    if (particles.count > 0 && laser.status == StepStatus::Applied) {
        // The particle filter weighs the scan's end points in the likelihood field: no ICP,
        // no innovation, no NIS; what tells how it went is how much weight survived.
        update_->setText(tr("t = %1 s: scan weighed (%2 points), N_eff %L3 of %L4 particles")
                             .arg(time, 0, 'f', 2)
                             .arg(laser.measured_points)
                             .arg(particles.effective, 0, 'f', 0)
                             .arg(particles.count));
    } else if (laser.status == StepStatus::Applied) {
        update_->setText(tr("t = %1 s: scan matched (%2 pts), V = (%3 cm, %4 cm, %5°), NIS %6")
                             .arg(time, 0, 'f', 2)
                             .arg(laser.icp.matched_points)
                             .arg(100.0 * laser.innovation(0), 0, 'f', 1)
                             .arg(100.0 * laser.innovation(1), 0, 'f', 1)
                             .arg(laser.innovation(2) * 180.0 / kPi, 0, 'f', 2)
                             .arg(laser.nis, 0, 'g', 3));
    } else {
        update_->setText(tr("t = %1 s: prediction only (%2)")
                             .arg(time, 0, 'f', 2)
                             .arg(laser_status_text(sample->snapshot, history_.scene().laser)));
    }
}

}  // namespace legofeup::ui
