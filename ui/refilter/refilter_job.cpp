#include "legofeup/ui/refilter/refilter_job.hpp"

#include <exception>
#include <utility>

namespace legofeup::ui {
namespace {

std::vector<Wall> walls_of(const lessons::RunConfig& config) {
    try {
        return lessons::resolve(config).world.walls;
    } catch (const std::exception&) {
        return {};  // a world file that moved: the overlay goes without walls
    }
}

}  // namespace

RefilterJob::RefilterJob(std::shared_ptr<const lessons::RunLog> log, lessons::RunConfig new_config)
    : BackgroundTask([log = std::move(log),
                      config = std::move(new_config)](const TaskProgress& progress) {
          return lessons::refilter(*log, config, [&progress](std::size_t done, std::size_t total) {
              return progress.report(static_cast<double>(done) / static_cast<double>(total));
          });
      }) {}

RunLogReadJob::RunLogReadJob(std::string path)
    : BackgroundTask([path = std::move(path)](const TaskProgress& progress) {
          ReadRunLog read;
          auto log = std::make_shared<lessons::RunLog>(lessons::load_run_log(path));
          read.walls = walls_of(log->config);  // read once, here, not per replay
          read.log = std::move(log);
          progress.report(1.0);
          return read;
      }) {}

}  // namespace legofeup::ui
