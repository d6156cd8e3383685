#include "legofeup/ui/run_history.hpp"

#include <QByteArray>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>
#include <utility>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/trace_csv.hpp"
#include "legofeup/ui/session/run_samples.hpp"

namespace legofeup::ui {

namespace {

constexpr float kRecordNaN = std::numeric_limits<float>::quiet_NaN();

float as_record_float(double value) {
    return static_cast<float>(value);
}
RecordedWheelSpeeds recorded_speeds(const WheelSpeeds& speeds) {
    return {as_record_float(speeds.right), as_record_float(speeds.left)};
}
std::array<float, 2> recorded_pair(const std::array<double, 2>& pair) {
    return {as_record_float(pair[0]), as_record_float(pair[1])};
}

void record_beacons(const BeaconUpdates& beacons, StepRecord& record) {
    const int count = std::min<int>(beacons.count, kMaxBeaconSightings);
    for (int i = 0; i < count; ++i) {
        const BeaconUpdate& update = beacons.updates[static_cast<std::size_t>(i)];
        if (!update.known || update.status == StepStatus::NotAttempted) {
            continue;
        }
        const auto k = static_cast<std::size_t>(record.bearing_count++);
        record.bearing_innovation[k] =
            as_record_float(wrap_angle(update.bearing - update.predicted));
        record.bearing_applied[k] = update.status == StepStatus::Applied;
    }
}

LaserNumbers laser_numbers(const LaserUpdate& laser) {
    LaserNumbers numbers;
    numbers.processed = laser.scan_received && !laser.wrong_beam_count;
    numbers.matched = laser.matched;
    numbers.updated = laser.status != StepStatus::NotAttempted;
    numbers.recovery_triggered = laser.recovery_triggered;
    numbers.matched_points = laser.icp.matched_points;
    numbers.consecutive_mismatches = laser.consecutive_mismatches;
    numbers.innovation = laser.innovation.cast<float>();
    return numbers;
}

}  // namespace

static_assert(sizeof(StepRecord) <= 264, "a record is kept for every step: keep it small");

StepRecord make_step_record(const RunSample& sample) {
    const LoopSnapshot& x = sample.snapshot;
    StepRecord record;
    record.time = x.time;
    record.estimate = to_pose(x.estimate);
    record.pxx = as_record_float(x.covariance(kX, kX));
    record.pxy = as_record_float(x.covariance(kX, kY));
    record.pyy = as_record_float(x.covariance(kY, kY));
    record.ptt = as_record_float(x.covariance(kTheta, kTheta));
    record.odometry =
        Eigen::Vector2f(as_record_float(x.odometry_pose.x), as_record_float(x.odometry_pose.y));
    record.wheels = recorded_speeds(x.wheels);
    for (std::size_t i = 0; i < record.ir_distance.size(); ++i) {
        const IrDistance& reading = x.ir[i].reading;
        record.ir_distance[i] = reading.in_range() ? as_record_float(reading.distance) : kRecordNaN;
    }
    if (x.update.status != StepStatus::NotAttempted && std::isfinite(x.update.nis)) {
        record.wall_nis = as_record_float(x.update.nis);
    }
    record.nees = sample.nees;
    if (sample.truth) {
        record.has_truth = true;
        record.teleports = sample.truth->teleports;
        record.truth = sample.truth->pose;
        record.true_wheel_speeds = recorded_speeds(sample.truth->wheel_surface_speeds);
        record.true_turn_rate = as_record_float(sample.truth->velocity.w);
    }
    record.localisation = x.localisation;
    record.filter_kind = x.filter_kind;
    record_beacons(x.beacons, record);
    record.has_gyro = x.readings.has_gyro;
    record.has_compass = x.readings.has_compass;
    record.has_accelerometers = x.readings.has_accelerometers;
    record.gyro_rate = as_record_float(x.readings.gyro_rate);
    record.gyro_heading = as_record_float(x.readings.gyro_heading);
    record.compass_heading = as_record_float(x.readings.compass_heading);
    record.speeds_valid = x.speeds.valid;
    record.wheel_kf = recorded_pair(x.speeds.wheel_kf);
    record.wheel_differentiated = recorded_pair(x.speeds.wheel_differentiated);
    record.encoder_turn_rate = as_record_float(x.speeds.body_encoders.w);
    record.fused_turn_rate = as_record_float(x.fused_velocity.w);
    record.shadow_active = x.shadow.active;
    record.shadow_kind = x.shadow.kind;
    record.shadow_position = Eigen::Vector2f(as_record_float(x.shadow.estimate(kX)),
                                             as_record_float(x.shadow.estimate(kY)));
    record.filter_seconds = as_record_float(x.filter_seconds);
    record.shadow_filter_seconds = as_record_float(x.shadow_filter_seconds);
    record.particle_effective = as_record_float(x.particles.effective);
    record.particle_count = x.particles.count;
    record.laser = laser_numbers(x.laser);
    return record;
}

/// The trace.csv rows of the run, written by the CLI's writer as the steps come. A row is
/// roughly 500 bytes of text (estimated from its columns); every kBlockBytes of rows are
/// deflated (zlib's fastest level, once every ~25 s of a 20 Hz run; the ratio is not measured
/// yet). Without the run's loop (a scene made by hand) only the header: the rows name its
/// walls.
class RunHistory::TraceRows {
  public:
    explicit TraceRows(std::shared_ptr<const LoopConfig> loop)
        : rows_(loop != nullptr),
          loop_(loop ? std::move(loop) : std::make_shared<const LoopConfig>()),
          writer_(text_, *loop_) {
        open_.reserve(kBlockBytes);
        flush();
    }
    void add(const RunSample& sample) {
        if (rows_) {
            writer_.on_step(sample.snapshot, truth_or_unknown(sample));
        }
    }
    /// Moves the rows written since the last flush into the open block, and packs it once
    /// it is full.
    void flush() {
        open_ += std::move(text_).str();
        text_.str({});
        if (open_.size() >= kBlockBytes) {
            packed_.push_back(qCompress(reinterpret_cast<const uchar*>(open_.data()),
                                        static_cast<qsizetype>(open_.size()), kLevel));
            packed_.back().squeeze();  // qCompress leaves the input's size reserved
            open_.clear();
        }
    }
    /// The rows' bytes: the deflated blocks and the open one.
    std::size_t bytes() const {
        std::size_t bytes = open_.capacity() + packed_.capacity() * sizeof(QByteArray);
        for (const QByteArray& block : packed_) {
            bytes += static_cast<std::size_t>(block.capacity());
        }
        return bytes;
    }
    std::string text() const {
        std::string all;
        for (const QByteArray& block : packed_) {
            const QByteArray rows = qUncompress(block);
            all.append(rows.constData(), static_cast<std::size_t>(rows.size()));
        }
        all += open_;
        return all;
    }

  private:
    static constexpr std::size_t kBlockBytes = std::size_t{256} << 10;
    static constexpr int kLevel = 1;
    bool rows_;                               ///< the run's loop is known: rows are written
    std::shared_ptr<const LoopConfig> loop_;  ///< the writer refers to it
    std::ostringstream text_;
    lessons::TraceCsvWriter writer_;
    std::string open_;                ///< the rows not yet packed
    std::vector<QByteArray> packed_;  ///< deflated blocks of rows, in order
};

RunHistory::RunHistory() : trace_(std::make_unique<TraceRows>(nullptr)) {}
RunHistory::~RunHistory() = default;
RunHistory::RunHistory(RunHistory&&) noexcept = default;
RunHistory& RunHistory::operator=(RunHistory&&) noexcept = default;

void RunHistory::restart(ArenaScene scene) {
    scene_ = std::move(scene);
    records_.clear();
    recent_.clear();
    older_.clear();
    next_kept_time_ = -std::numeric_limits<double>::infinity();
    trace_ = std::make_unique<TraceRows>(scene_.loop);
    ++epoch_;
}

void RunHistory::update_scene(ArenaScene scene) {
    scene_ = std::move(scene);
}

void RunHistory::append(std::vector<RunSample>&& batch) {
    for (RunSample& sample : batch) {
        records_.push_back(make_step_record(sample));
        trace_->add(sample);
        recent_.push_back(std::move(sample));
    }
    trace_->flush();
    drop_old_samples(batch.size());
}

void RunHistory::drop_old_samples(std::size_t batch_size) {
    const std::size_t keep = std::max(kRecentSamples, batch_size);
    while (recent_.size() > keep) {
        const std::size_t step = recent_begin();
        RunSample& oldest = recent_.front();
        if (oldest.snapshot.time >= next_kept_time_) {
            next_kept_time_ = oldest.snapshot.time + kKeptPeriod;
            oldest.particles.reset();  // 16 kB a cloud: kept for the recent samples only
            older_.push_back({step, std::move(oldest)});
        }
        recent_.pop_front();
    }
}

const RunSample* RunHistory::sample(std::size_t step) const {
    if (step >= records_.size()) {
        return nullptr;
    }
    if (step >= recent_begin()) {
        return &recent_[step - recent_begin()];
    }
    const auto found = std::lower_bound(
        older_.begin(), older_.end(), step,
        [](const KeptSample& kept, std::size_t wanted) { return kept.step < wanted; });
    return found != older_.end() && found->step == step ? &found->sample : nullptr;
}

std::pair<std::size_t, const RunSample*> RunHistory::nearest_sample(std::size_t step) const {
    if (records_.empty()) {
        return {0, nullptr};
    }
    step = std::min(step, records_.size() - 1);
    if (step >= recent_begin()) {
        return {step, &recent_[step - recent_begin()]};
    }
    // The first kept sample at or after `step`: an older one, or the first recent one.
    const auto later = std::lower_bound(
        older_.begin(), older_.end(), step,
        [](const KeptSample& kept, std::size_t wanted) { return kept.step < wanted; });
    std::pair<std::size_t, const RunSample*> after{recent_begin(), &recent_.front()};
    if (later != older_.end()) {
        after = {later->step, &later->sample};
    }
    if (later == older_.begin()) {
        return after;
    }
    const KeptSample& before = *std::prev(later);
    return step - before.step < after.first - step ? std::pair{before.step, &before.sample} : after;
}

std::string RunHistory::trace_csv() const {
    return trace_->text();
}

RunHistory::Bytes RunHistory::bytes() const {
    Bytes bytes;
    bytes.records = records_.capacity() * sizeof(StepRecord);
    bytes.samples = (recent_.size() + older_.size()) * sizeof(RunSample);
    bytes.trace = trace_->bytes();
    for (const RunSample& sample : recent_) {
        if (sample.particles) {
            bytes.particles += sample.particles->capacity() * sizeof(ParticlePoint);
        }
    }
    return bytes;
}

}  // namespace legofeup::ui
