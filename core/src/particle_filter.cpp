#include "legofeup/core/particle_filter.hpp"

#include <algorithm>
#include <limits>

#include "legofeup/core/small_angle_sincos.hpp"

namespace legofeup {

ParticleFilter::ParticleFilter() {
    resize(static_cast<std::size_t>(tuning_.particle_count));
    reset(StateVector::Zero(), StateCovariance::Identity());
}

void ParticleFilter::resize(std::size_t count) {
    for (std::vector<double>* column :
         {&x_, &y_, &theta_, &weight_, &logl_, &next_x_, &next_y_, &next_theta_}) {
        column->resize(count);
    }
}

void ParticleFilter::configure(const PoseEstimatorSettings& settings) {
    set_limits(settings.limits);
    seed_ = settings.seed;
    free_space_ = settings.free_space;
    const auto count = static_cast<std::size_t>(std::max(1, settings.particles.particle_count));
    tuning_ = settings.particles;
    if (count != x_.size()) {
        resample(count);  // the same distribution, in the new number of particles
        weighed_effective_ = 0.0;
        publish();
    }
}

// A new cloud of particle_count particles, each drawn by `draw`, with equal weights and the
// random stream and recovery averages started again.
template <class Draw>
bool ParticleFilter::start_cloud(Draw&& draw) {
    random_.reseed(seed_);
    const auto count = static_cast<std::size_t>(std::max(1, tuning_.particle_count));
    resize(count);
    const double equal = 1.0 / static_cast<double>(count);
    for (std::size_t i = 0; i < count; ++i) {
        set_particle(i, draw());
        weight_[i] = equal;
    }
    w_slow_ = 0.0;
    w_fast_ = 0.0;
    pending_inject_ = 0.0;
    weighed_effective_ = 0.0;
    summary_ = {};
    return publish() == StepStatus::Applied;
}

bool ParticleFilter::reset(const StateVector& x, const StateCovariance& P) {
    if (!x.allFinite() || !P.allFinite()) {
        return false;
    }
    StateCovariance root;
    if (!psd_square_root<kStateSize>(0.5 * (P + P.transpose()), root)) {
        root = P.diagonal().cwiseMax(0.0).cwiseSqrt().asDiagonal();
    }
    return start_cloud([&] {
        StateVector n;
        for (int k = 0; k < kStateSize; ++k) {  // in order: a constructor's arguments need not be
            n(k) = random_.normal();
        }
        return StateVector(x + root * n);
    });
}

bool ParticleFilter::reset_uniform() {
    if (!free_space_ || free_space_->empty()) {
        return false;
    }
    return start_cloud([this] { return random_pose(); });
}

StepStatus ParticleFilter::update(const ScanLikelihood& scan) {
    if (scan.endpoints.empty()) {
        return StepStatus::NotAttempted;
    }
    return weigh(
        [&scan](double x, double y, double theta) {
            return scan_log_likelihood(scan.field, Pose2{x, y, theta}, scan.endpoints, scan.params,
                                       scan.range_max);
        },
        static_cast<int>(scan.endpoints.size()));
}

StateVector ParticleFilter::random_pose() {
    const std::array<double, 4> u{random_.uniform(), random_.uniform(), random_.uniform(),
                                  random_.uniform()};
    return to_state(free_space_->sample(u));
}

StepStatus ParticleFilter::apply_likelihoods(int dimension) {
    const std::size_t count = x_.size();
    // 2. wᵢ ← wᵢ·p(z | Xᵢ), scaled by the largest likelihood so that no exp overflows; NaN
    // likelihoods (a particle the model cannot judge) count as impossible.
    double best = -std::numeric_limits<double>::infinity();
    for (const double value : logl_) {
        if (value > best) {
            best = value;
        }
    }
    if (!std::isfinite(best)) {
        return StepStatus::RejectedNonFinite;  // all particles impossible: weights kept
    }
    double total = 0.0;
    double average = 0.0;  // Σ wᵢ·p(z | Xᵢ)/p_best: the prior-weighted mean likelihood
    for (std::size_t i = 0; i < count; ++i) {
        const double ratio = logl_[i] == logl_[i] ? std::exp(logl_[i] - best) : 0.0;
        average += weight_[i] * ratio;
        next_x_[i] = weight_[i] * ratio;  // the unnormalised posterior weight
        total += next_x_[i];
    }
    if (!(total > 0.0)) {
        // The prior weights sit where the likelihood underflowed: weigh in the log domain.
        double best_posterior = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < count; ++i) {
            next_x_[i] = weight_[i] > 0.0 && logl_[i] == logl_[i]
                             ? std::log(weight_[i]) + logl_[i]
                             : -std::numeric_limits<double>::infinity();
            best_posterior = std::max(best_posterior, next_x_[i]);
        }
        if (!std::isfinite(best_posterior)) {
            return StepStatus::RejectedNonFinite;
        }
        total = 0.0;
        for (std::size_t i = 0; i < count; ++i) {
            next_x_[i] = std::exp(next_x_[i] - best_posterior);
            total += next_x_[i];
        }
        average = std::exp(best_posterior - best);
    }
    for (std::size_t i = 0; i < count; ++i) {
        weight_[i] = next_x_[i] / total;
    }

    // 3. The likelihood per reading, averaged long- and short-term (Table 8.3 lines 8–10).
    // p_avg = Σ wᵢ p(z | Xᵢ) = p_best·average; per reading its 1/dimension-th power.
    const double per_reading =
        std::exp((best + std::log(std::max(average, std::numeric_limits<double>::min())))
                 / std::max(1, dimension));
    if (w_slow_ <= 0.0) {
        w_slow_ = per_reading;  // the first update: both averages start at the first value
        w_fast_ = per_reading;
    } else {
        w_slow_ += tuning_.alpha_slow * (per_reading - w_slow_);
        w_fast_ += tuning_.alpha_fast * (per_reading - w_fast_);
    }
    // The share of the cloud the next update first replaces by free-space draws (Table 8.3
    // line 13's probability; applied before that update weighs them, see inject_pending).
    const bool can_inject = tuning_.recovery && free_space_ && !free_space_->empty();
    pending_inject_ = can_inject ? std::max(0.0, 1.0 - w_fast_ / w_slow_) : 0.0;

    // 4. Resample when the weights have degenerated. The N_eff published is this one: after
    // a resampling the weights are equal and 1/Σwᵢ² is N, which would hide what the scan told.
    weighed_effective_ = effective_count();
    summary_.resampled = false;
    if (weighed_effective_ < tuning_.resample_threshold * static_cast<double>(count)) {
        resample(count);
        summary_.resampled = true;
    }
    return publish();
}

// Table 4.4 (low-variance sampler): one uniform r ∈ [0, 1/N); the m-th new particle is the
// old one whose cumulative weight interval holds r + m/N. Every particle of weight w gets
// ⌊N·w⌋ or ⌈N·w⌉ copies, N·w on average, with less variance than N independent draws.
void ParticleFilter::resample(std::size_t count) {
    const std::size_t old_count = x_.size();
    next_x_.resize(count);
    next_y_.resize(count);
    next_theta_.resize(count);
    const double step = 1.0 / static_cast<double>(count);
    const double start = random_.uniform() * step;
    std::size_t source = 0;
    double cumulative = weight_[0];
    for (std::size_t m = 0; m < count; ++m) {
        const double target = start + static_cast<double>(m) * step;
        while (target > cumulative && source + 1 < old_count) {
            ++source;
            cumulative += weight_[source];
        }
        next_x_[m] = x_[source];
        next_y_[m] = y_[source];
        next_theta_[m] = theta_[source];
    }
    x_.swap(next_x_);
    y_.swap(next_y_);
    theta_.swap(next_theta_);
    resize(count);
    std::fill(weight_.begin(), weight_.end(), step);
}

// Augmented MCL's injection (Table 8.3 lines 12–19), done at the start of the update after
// the one that decided it rather than inside its resampling: each particle is replaced, with
// probability pending_inject_, by a pose drawn from the free space, keeping its weight. The
// injected poses are weighed by this update's measurement before anything is published, so
// the estimate never averages in guesses no measurement has judged (Thrun's order publishes
// them until the next update, which in the wall lessons can be seconds away).
void ParticleFilter::inject_pending() {
    summary_.injected = 0;
    if (!(pending_inject_ > 0.0) || !free_space_ || free_space_->empty()) {
        return;
    }
    for (std::size_t i = 0; i < x_.size(); ++i) {
        if (random_.uniform() < pending_inject_) {
            set_particle(i, random_pose());
            ++summary_.injected;
        }
    }
    // The averages go on (Table 8.3; ROS AMCL restarts them after an injection, which
    // leaves one draw of a few per cent to find a kidnapped robot): the filter injects for as
    // long as its short-term fit stays below its long-term one.
    pending_inject_ = 0.0;
}

double ParticleFilter::effective_count() const {
    double sum_squares = 0.0;
    for (const double w : weight_) {
        sum_squares += w * w;
    }
    return 1.0 / sum_squares;
}

StepStatus ParticleFilter::publish() {
    const std::size_t count = x_.size();
    // 5. x̄ = Σ wᵢ Xᵢ with θ̄ = atan2(Σ wᵢ sin θᵢ, Σ wᵢ cos θᵢ); P = Σ wᵢ (Xᵢ − x̄)(Xᵢ − x̄)ᵀ with
    // the heading differences wrapped. The circular mean is taken relative to one particle's
    // heading θ₀ (θ̄ = θ₀ + atan2(Σ wᵢ sin(θᵢ − θ₀), Σ wᵢ cos(θᵢ − θ₀)), the same angle): a
    // cloud of one particle, or of particles all at one heading, then publishes that heading
    // to the bit, as dead reckoning does. The relative headings lie within ±2π, where
    // small_angle_sincos gives libm's sines and cosines to 2·10⁻¹⁶ at a fifth of the cost.
    const double reference = theta_[0];
    double mx = 0.0;
    double my = 0.0;
    double ms = 0.0;
    double mc = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double w = weight_[i];
        mx += w * x_[i];
        my += w * y_[i];
        const SinCos relative = small_angle_sincos(theta_[i] - reference);
        ms += w * relative.sin;
        mc += w * relative.cos;
    }
    const double heading =
        wrap_angle(reference + (ms == 0.0 && mc == 0.0 ? 0.0 : std::atan2(ms, mc)));
    StateCovariance P = StateCovariance::Zero();
    double near = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double w = weight_[i];
        const StateVector d(x_[i] - mx, y_[i] - my, wrap_angle(theta_[i] - heading));
        P.noalias() += w * d * d.transpose();
        if (d(kX) * d(kX) + d(kY) * d(kY) <= kNearMeanRadius * kNearMeanRadius) {
            near += w;
        }
    }
    summary_.count = static_cast<int>(count);
    summary_.effective = weighed_effective_ > 0.0 ? weighed_effective_ : effective_count();
    summary_.near_mean_share = near;
    summary_.w_slow = w_slow_;
    summary_.w_fast = w_fast_;
    return commit(StateVector(mx, my, heading), P);
}

}  // namespace legofeup
