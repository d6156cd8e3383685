// The settings table: the further lessons' simulated sensors (off unless enabled: the beacon
// scanner, the gyro, the accelerometers, the compass) and the displacement event. Validation
// names them "simulator.<sensor>.<name>"; they are the simulator's, so they wait for the next
// start, and every run may have them (for its plots).

#include "setting_builders.hpp"

namespace legofeup::lessons {

using namespace setting_builders;

void add_simulated_sensor_settings(std::vector<Setting>& s) {
    s.push_back(boolean(
        {.key = "beacon_scanner.enabled",
         .field = "simulator.beacon_scanner.enabled",
         .label = in_words("enabled"),
         .help = tr_noop("simulate the 360° bearing-only beacon scanner"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.beacon_scanner.enabled; }));
    s.push_back(real(
        {.key = "beacon_scanner.detection_probability",
         .field = "simulator.beacon_scanner.detection_probability",
         .label = in_words("detection probability"),
         .help = tr_noop("probability of seeing each beacon in line of sight per scan, 0 … 1"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.beacon_scanner.detection_probability; }));
    s.push_back(real(
        {.key = "beacon_scanner.bearing_noise",
         .field = "simulator.beacon_scanner.bearing_noise",
         .label = in_words("bearing noise"),
         .help = tr_noop("σ of each bearing, rad"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.beacon_scanner.bearing_noise; }));
    s.push_back(real(
        {.key = "beacon_scanner.period",
         .field = "simulator.beacon_scanner.period",
         .label = in_words("period"),
         .help = tr_noop("s between scans"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.beacon_scanner.period; }));
    s.push_back(boolean(
        {.key = "gyro.enabled",
         .field = "simulator.gyro.enabled",
         .label = in_words("enabled"),
         .help = tr_noop("simulate the single-axis gyroscope"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.gyro.enabled; }));
    s.push_back(real(
        {.key = "gyro.offset",
         .field = "simulator.gyro.offset",
         .label = in_words("offset"),
         .help = tr_noop("raw value at rest, counts"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.gyro.offset; }));
    s.push_back(real(
        {.key = "gyro.noise",
         .field = "simulator.gyro.noise",
         .label = in_words("noise"),
         .help = tr_noop("σ of the gyro's white noise, counts"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.gyro.noise; }));
    s.push_back(real(
        {.key = "gyro.bias_sigma",
         .field = "simulator.gyro.bias_sigma",
         .label = in_words("bias sigma"),
         .help = tr_noop("σ of the gyro bias drawn at the start, counts"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.gyro.bias_sigma; }));
    s.push_back(real(
        {.key = "gyro.bias_drift",
         .field = "simulator.gyro.bias_drift",
         .label = in_words("bias drift"),
         .help = tr_noop("random walk of the gyro bias, counts/√s"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.gyro.bias_drift; }));
    s.push_back(boolean(
        {.key = "accelerometers.enabled",
         .field = "simulator.accelerometers.enabled",
         .label = in_words("enabled"),
         .help = tr_noop("simulate the two accelerometers over the wheels"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.accelerometers.enabled; }));
    s.push_back(real(
        {.key = "accelerometers.noise",
         .field = "simulator.accelerometers.noise",
         .label = in_words("noise"),
         .help = tr_noop("σ of each axis's white noise, counts"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.accelerometers.noise; }));
    s.push_back(real(
        {.key = "accelerometers.bias_sigma",
         .field = "simulator.accelerometers.bias_sigma",
         .label = in_words("bias sigma"),
         .help = tr_noop("σ of each axis's constant bias, counts"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.accelerometers.bias_sigma; }));
    s.push_back(boolean(
        {.key = "compass_sensor.enabled",
         .field = "simulator.compass_sensor.enabled",
         .label = in_words("enabled"),
         .help = tr_noop("simulate the magnetic compass"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.compass.enabled; }));
    s.push_back(real(
        {.key = "compass_sensor.noise_deg",
         .field = "simulator.compass_sensor.noise_deg",
         .label = in_words("noise deg"),
         .help = tr_noop("σ of the compass noise before 1° rounding, °"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.compass.noise_deg; }));
    s.push_back(boolean(
        {.key = "displacement.enabled",
         .field = "simulator.displacement.enabled",
         .label = in_words("enabled"),
         .help = tr_noop("move the robot suddenly once (the filter is not told)"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.displacement.enabled; }));
    s.push_back(real(
        {.key = "displacement.time",
         .field = "simulator.displacement.time",
         .label = in_words("time"),
         .help = tr_noop("simulated time of the displacement, s"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.displacement.time; }));
    s.push_back(real(
        {.key = "displacement.dx",
         .field = "simulator.displacement.dx",
         .label = in_words("dx"),
         .help = tr_noop("displacement along the world x axis, m"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.displacement.dx; }));
    s.push_back(real(
        {.key = "displacement.dy",
         .field = "simulator.displacement.dy",
         .label = in_words("dy"),
         .help = tr_noop("displacement along the world y axis, m"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.displacement.dy; }));
    s.push_back(degrees(
        {.key = "displacement.dtheta_deg",
         .field = "simulator.displacement.dtheta",
         .label = in_words("dtheta deg"),
         .help = tr_noop("turn of the displacement, °"),
         .page = SettingPage::SimulatedSensors,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.displacement.dtheta; }));
}

}  // namespace legofeup::lessons
