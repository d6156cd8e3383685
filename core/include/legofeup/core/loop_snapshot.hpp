#pragma once
// Everything one step of the loop computed: the output the GUI, the CLI and the metrics read.
// A plain value (no pointers, no heap), so it can be copied across threads and recorded.

#include <array>
#include <cstdint>

#include "legofeup/core/controller.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/motion.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/core/sensor_frame.hpp"
#include "legofeup/core/sharp_ir.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/core/wall_association.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {

struct IrSample {
    std::uint16_t adc = 0;  ///< raw A/D value A
    IrDistance reading;     ///< eq. 2 and the range check
};

using WallUpdateReport = UpdateReport<WallMeasurement::kSize, kStateSize>;

struct LoopSnapshot {
    std::uint64_t step = 0;      ///< frames processed since the last reset (1 for the first)
    double time = 0.0;           ///< the frame's time stamp, s
    std::uint32_t sequence = 0;  ///< the frame's sequence number
    /// No frame came this period (lost or late on a real link): the loop only predicted,
    /// with no odometry increment, and the controller ran on the prediction.
    bool frame_missing = false;
    /// The raw frame exactly as the loop received it, for recording and replay
    /// (lessons/recording); when frame_missing, a default frame stamped with the due time.
    SensorFrame frame;

    // Estimation module.
    StateVector estimate = StateVector::Zero();            ///< X̂ after this step
    StateCovariance covariance = StateCovariance::Zero();  ///< P after this step
    Pose2 odometry_pose;           ///< dead reckoning from the same counts (no updates ever)
    OdometryIncrement increment;   ///< this period's d1, d2, d, Δθ
    bool odometry_glitch = false;  ///< encoder jump beyond max_wheel_travel_per_step: skipped
    StepStatus predict_status = StepStatus::NotAttempted;

    // Observation and association modules.
    std::array<IrSample, kIrSensorCount> ir{};
    bool observation_available = false;  ///< both readings in range
    WallObservation observation;         ///< eq. 3 (valid when observation_available)
    AssociationResult association;       ///< outcome NoObservation when there was none
    WallUpdateReport update;             ///< status NotAttempted when no update ran

    // Control module.
    ControllerStatus controller;
    VelocityCommand velocity;  ///< (V, W) from the routine
    WheelSpeeds wheels;        ///< (V1, V2) sent to the robot (eq. 1, speed-limited)
};

}  // namespace legofeup
