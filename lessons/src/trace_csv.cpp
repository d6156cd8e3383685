#include "legofeup/lessons/trace_csv.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "legofeup/core/consistency.hpp"

namespace legofeup::lessons {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();  // written as an empty cell

// Fixed, locale-independent formatting: the same run gives the same bytes.
void number(std::ostream& out, double value) {
    if (std::isfinite(value)) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", value);
        out << text;
    }
    out << ',';
}

}  // namespace

const char* trace_csv_header() {
    return "t,x_true,y_true,th_true,x_est,y_est,th_est,pxx,pxy,pxt,pyy,pyt,ptt,"
           "x_odo,y_odo,th_odo,ds1,ds2,v1,v2,wall,nis,nees,"
           "adc1,adc2,association,update,touching_wall,frame_missing";
}

TraceCsvWriter::TraceCsvWriter(std::ostream& out, const LoopConfig& loop) : out_(out), loop_(loop) {
    out_ << trace_csv_header() << '\n';
}

void TraceCsvWriter::on_step(const LoopSnapshot& s, const GroundTruth& truth) {
    number(out_, s.time);
    number(out_, truth.pose.x);
    number(out_, truth.pose.y);
    number(out_, truth.pose.theta);
    number(out_, s.estimate(kX));
    number(out_, s.estimate(kY));
    number(out_, s.estimate(kTheta));
    const StateCovariance& P = s.covariance;
    for (const auto& [row, column] :
         {std::pair{kX, kX}, std::pair{kX, kY}, std::pair{kX, kTheta}, std::pair{kY, kY},
          std::pair{kY, kTheta}, std::pair{kTheta, kTheta}}) {
        number(out_, P(row, column));
    }
    number(out_, s.odometry_pose.x);
    number(out_, s.odometry_pose.y);
    number(out_, s.odometry_pose.theta);
    for (const IrSample& ir : s.ir) {
        number(out_, ir.reading.status == IrStatus::Unavailable ? kNone : ir.reading.distance);
    }
    number(out_, s.wheels.right);
    number(out_, s.wheels.left);
    if (s.association.associated()) {
        out_ << loop_.walls.wall(s.association.wall).name;
    }
    out_ << ',';
    number(out_, s.update.status == StepStatus::Applied ? s.update.nis : kNone);
    number(out_, normalized_estimation_error(to_state(truth.pose), s.estimate, s.covariance));
    out_ << s.ir[0].adc << ',' << s.ir[1].adc << ',' << to_string(s.association.outcome) << ','
         << to_string(s.update.status) << ',' << (truth.touching_wall ? 1 : 0) << ','
         << (s.frame_missing ? 1 : 0) << '\n';
}

}  // namespace legofeup::lessons
