#include "legofeup/nxtemu/emulated_nxt.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "legofeup/comms/nxt/transport.hpp"
#include "legofeup/nxtemu/simulated_hardware.hpp"

namespace legofeup::nxtemu {
namespace {

namespace fs = std::filesystem;
namespace nxt = comms::nxt;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr std::uint32_t kAnyAddress = 0;
constexpr auto kAcceptPoll = 200ms;
constexpr double kDegreesPerSecondPerRpm = 6.0;

/// Makes `link` a symbolic link to `target`, atomically replacing a link already there;
/// refuses to replace anything else.
void point_link(const fs::path& link, const std::string& target) {
    const fs::file_status existing = fs::symlink_status(link);
    if (fs::exists(existing) && !fs::is_symlink(existing)) {
        throw std::invalid_argument("--pty-link " + link.string()
                                    + " exists and is not a symbolic link: not replacing it");
    }
    const fs::path temporary = link.string() + ".new";
    fs::remove(temporary);
    fs::create_symlink(target, temporary);
    fs::rename(temporary, link);
}

}  // namespace

struct EmulatedNxt::State {
    explicit State(EmulatorOptions o) : options(std::move(o)), started(Clock::now()) {
        const lessons::ResolvedRun run = resolve_emulated_run(options.run);
        FirmwareOptions firmware_options = options.firmware;
        firmware_options.wiring = options.wiring;
        firmware_options.max_motor_degrees_per_second =
            run.robot.max_motor_rpm * kDegreesPerSecondPerRpm;
        hardware = std::make_unique<SimulatedHardware>(run, options.wiring, [this] {
            const std::lock_guard lock(firmware_mutex);
            if (firmware) {
                firmware->advance(now());
            }
        });
        {
            const std::lock_guard lock(firmware_mutex);
            firmware = std::make_unique<BrickFirmware>(*hardware, firmware_options);
        }
        BrickServerOptions link = options.link;
        link.log = [this](const std::string& message) { log(message); };
        server = std::make_unique<BrickServer>(
            [this](std::span<const std::uint8_t> request) {
                const std::lock_guard lock(firmware_mutex);
                return firmware->handle(request, now());
            },
            std::move(link));
    }

    ~State() { stop(); }

    double now() const { return std::chrono::duration<double>(Clock::now() - started).count(); }

    void log(const std::string& message) const {
        if (options.log) {
            std::array<char, 32> stamp{};
            std::snprintf(stamp.data(), stamp.size(), "[%9.3f s] ", now());
            options.log(stamp.data() + message);
        }
    }

    /// After a session: a brick whose host vanished keeps doing what it was told.
    void session_ended(SessionEnd end) {
        log("session ended: " + std::string(to_string(end)));
        bool running = false;
        {
            const std::lock_guard lock(firmware_mutex);
            for (const double speed : firmware->motor_speeds()) {
                running = running || speed != 0.0;
            }
        }
        if (running && end != SessionEnd::Stopped) {
            log("warning: the motors are still running, as they would on a real brick "
                "(the relay program, if running, stops them after 500 ms without a read)");
        }
    }

    /// Runs a serving loop on its thread: a failure ends that transport, said in the log,
    /// and not the program.
    template <typename Loop>
    void guarded(const std::string& what, Loop loop) {
        try {
            loop();
        } catch (const std::exception& error) {
            log(what + " failed and serves no more: " + error.what());
        }
    }

    void serve_tcp_clients(nxt::TcpListener& listener) {
        while (!stopping) {
            std::unique_ptr<nxt::ByteStream> stream = listener.accept(kAcceptPoll);
            if (!stream) {
                continue;
            }
            log("host connected: " + stream->describe());
            session_ended(server->serve(*stream));
        }
    }

    void serve_pty_clients(std::string link_path) {
        while (!stopping) {
            std::unique_ptr<nxt::ByteStream> master;
            {
                const std::lock_guard lock(pty_mutex);
                master = pty->take_master();
            }
            const SessionEnd end = server->serve(*master);
            session_ended(end);
            if (end == SessionEnd::Stopped || stopping) {
                return;
            }
            // The master was closed (the host saw a hang-up, as after a lost Bluetooth link):
            // a new pseudo-terminal takes its place.
            const std::lock_guard lock(pty_mutex);
            pty = std::make_unique<nxt::PseudoTerminal>();
            if (!link_path.empty()) {
                point_link(link_path, pty->slave_path());
            }
            log("new pseudo-terminal " + pty->slave_path()
                + (link_path.empty() ? "" : " (" + link_path + " points to it)"));
        }
    }

    void stop() {
        const std::lock_guard lock(stop_mutex);
        stopping = true;
        if (server) {
            server->stop();
        }
        for (std::jthread& thread : threads) {
            if (thread.joinable()) {
                thread.join();
            }
        }
        threads.clear();
        remove_pty_link();
        if (hardware) {
            hardware->stop();
        }
    }

    /// The link would soon point to another program's pseudo-terminal: it goes with ours.
    void remove_pty_link() {
        const std::lock_guard lock(pty_mutex);
        std::error_code error;
        if (!pty_link.empty() && pty && fs::read_symlink(pty_link, error) == pty->slave_path()) {
            fs::remove(pty_link, error);
        }
        pty_link.clear();
    }

    EmulatorOptions options;
    Clock::time_point started;
    std::mutex firmware_mutex;  // guards firmware (hardware's pump and the server's sessions)
    std::unique_ptr<SimulatedHardware> hardware;
    std::unique_ptr<BrickFirmware> firmware;
    std::unique_ptr<BrickServer> server;
    std::atomic<bool> stopping{false};
    std::mutex stop_mutex;
    mutable std::mutex pty_mutex;  // guards pty
    std::unique_ptr<nxt::PseudoTerminal> pty;
    std::string pty_link;
    std::vector<std::unique_ptr<nxt::TcpListener>> listeners;
    std::vector<std::jthread> threads;
};

EmulatedNxt::EmulatedNxt(EmulatorOptions options)
    : state_(std::make_unique<State>(std::move(options))) {}

EmulatedNxt::~EmulatedNxt() {
    stop();
}

std::uint16_t EmulatedNxt::serve_tcp(std::uint16_t port, bool allow_remote) {
    State& s = *state_;
    const std::lock_guard lock(s.stop_mutex);
    auto listener = std::make_unique<nxt::TcpListener>(
        allow_remote ? kAnyAddress : comms::kLoopbackAddress, port);
    const std::uint16_t bound = listener->port();
    nxt::TcpListener& serving = *listener;
    s.listeners.push_back(std::move(listener));
    s.threads.emplace_back(
        [&s, &serving] { s.guarded("the TCP listener", [&] { s.serve_tcp_clients(serving); }); });
    s.log("listening on tcp:" + std::string(allow_remote ? "0.0.0.0" : "127.0.0.1") + ":"
          + std::to_string(bound));
    return bound;
}

std::string EmulatedNxt::serve_pty(const std::string& link_path) {
    State& s = *state_;
    const std::lock_guard lock(s.stop_mutex);
    std::string path;
    {
        const std::lock_guard pty_lock(s.pty_mutex);
        if (s.pty) {
            throw std::logic_error("serve_pty: a pseudo-terminal is served already");
        }
        s.pty = std::make_unique<nxt::PseudoTerminal>();
        s.pty_link = link_path;
        path = s.pty->slave_path();
    }
    if (!link_path.empty()) {
        point_link(link_path, path);
    }
    s.threads.emplace_back([&s, link_path] {
        s.guarded("the pseudo-terminal", [&] { s.serve_pty_clients(link_path); });
    });
    s.log("serving the pseudo-terminal " + path
          + (link_path.empty() ? "" : " (" + link_path + " points to it)"));
    return path;
}

std::string EmulatedNxt::pty_path() const {
    const std::lock_guard lock(state_->pty_mutex);
    return state_->pty ? state_->pty->slave_path() : std::string();
}

comms::Endpoint EmulatedNxt::truth_endpoint() const {
    return state_->hardware->truth_endpoint();
}

simserver::BoundPorts EmulatedNxt::simulator_ports() const {
    return state_->hardware->simulator_ports();
}

void EmulatedNxt::stop() {
    state_->stop();
}

EmulatorCounters EmulatedNxt::counters() const {
    State& s = *state_;
    EmulatorCounters counters;
    counters.link = s.server->counters();
    {
        const std::lock_guard lock(s.firmware_mutex);
        counters.firmware = s.firmware->counters();
    }
    counters.simulator_frames = s.hardware->frames();
    counters.simulator_frames_missed = s.hardware->missed_frames();
    return counters;
}

}  // namespace legofeup::nxtemu
