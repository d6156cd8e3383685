// The covariance panel's line under the σs: a wall update, or the test that refused the wall.

#include <gtest/gtest.h>

#include "legofeup/core/walls.hpp"
#include "legofeup/ui/panels/covariance_view.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {
namespace {

ArenaScene standard_scene() {
    ArenaScene scene;
    scene.walls = standard_arena_walls(ArenaSpec{}).walls();
    return scene;
}

LoopSnapshot refused(AssociationOutcome outcome) {
    LoopSnapshot s;
    s.time = 12.5;
    s.association.outcome = outcome;
    s.association.wall = 0;
    s.association.angle_error = degrees_to_radians(25.0);
    s.association.distance_error = -0.152;
    s.association.mahalanobis_d2 = 136.2;
    s.association.mahalanobis_threshold = 9.2103;
    return s;
}

std::string text_of(const LoopSnapshot& s, const ArenaScene& scene) {
    return CovarianceView::wallUpdateText(s, scene).toStdString();
}

TEST(CovarianceViewText, NamesTheFixedDistanceGateWithItsErrorAndLimit) {
    EXPECT_EQ(text_of(refused(AssociationOutcome::DistanceMismatch), standard_scene()),
              "t = 12.50 s: prediction only: wall_y- refused by the fixed distance gate (D_c "
              "error -15.2 cm, limit 10.0 cm; the Mahalanobis d² would be 136.2).");
}

TEST(CovarianceViewText, NamesTheFixedAngleGateWithItsErrorAndLimit) {
    EXPECT_EQ(text_of(refused(AssociationOutcome::AngleMismatch), standard_scene()),
              "t = 12.50 s: prediction only: wall_y- refused by the fixed angle gate (ObsAng "
              "error 25.0°, limit 20.0°).");
}

TEST(CovarianceViewText, NamesTheMahalanobisGateWithD2AndItsThreshold) {
    ArenaScene scene = standard_scene();
    scene.association.gate = AssociationGate::Mahalanobis;
    EXPECT_EQ(text_of(refused(AssociationOutcome::MahalanobisMismatch), scene),
              "t = 12.50 s: prediction only: wall_y- refused by the Mahalanobis gate (d² = 136.2 "
              "above χ²(2) = 9.21 at p = 0.99).");
}

TEST(CovarianceViewText, AnAppliedUpdateShowsItsInnovationAndNis) {
    LoopSnapshot s = refused(AssociationOutcome::Associated);
    s.update.status = StepStatus::Applied;
    s.update.innovation << -0.012, degrees_to_radians(1.5);
    s.update.nis = 1.25;
    EXPECT_EQ(text_of(s, standard_scene()),
              "t = 12.50 s: wall update, innovation (-0.0120 m, 1.50°), NIS 1.25");
}

TEST(CovarianceViewText, WithoutACandidateItIsPredictionOnly) {
    EXPECT_EQ(text_of(LoopSnapshot{}, standard_scene()),
              "t = 0.00 s: prediction only (no wall update)");
}

}  // namespace
}  // namespace legofeup::ui
