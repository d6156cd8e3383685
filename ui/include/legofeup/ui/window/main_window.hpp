#pragma once
// The LegoFeup Lab window: the arena in the middle, the plots below, the lesson and the
// covariance matrix on the left, the configuration on the right. It builds the docks and
// menus and wires signals — nothing else: the session owns the run, each widget its job.

#include <QMainWindow>

class QAction;
class QDockWidget;
class QLabel;
class QTimer;

namespace legofeup::ui {

class ArenaView;
class ConfigPanel;
class IrCalibrationDialog;
class RobotStatusView;
class UmbmarkDialog;
class CovarianceView;
class FileActions;
class LessonActions;
class LessonPanel;
class RefilterDialog;
class KeyboardDriver;
class KidnapAction;
class PlotsPanel;
class RunToolBar;
class Session;

class MainWindow : public QMainWindow {
    Q_OBJECT

  public:
    explicit MainWindow(Session& session, QWidget* parent = nullptr);
    ~MainWindow() override;

    ArenaView& arena() const { return *arena_; }
    PlotsPanel& plots() const { return *plots_; }
    ConfigPanel& configPanel() const { return *config_; }
    LessonPanel& lessonPanel() const { return *lesson_; }
    LessonActions& lessonActions() const { return *lesson_files_; }
    CovarianceView& covarianceView() const { return *covariance_; }
    RunToolBar& runToolBar() const { return *toolbar_; }
    KeyboardDriver& keyboard() const { return *keyboard_; }
    /// Run ▸ Kidnap robot… (also on the toolbar).
    KidnapAction& kidnap() const { return *kidnap_; }
    FileActions& fileActions() const { return *files_; }
    RobotStatusView& robotStatus() const { return *robot_; }
    /// Run ▸ Reconnect: enabled after a failed run.
    QAction* reconnectAction() const { return reconnect_; }

    /// The projector view: everything's text 1.6× larger.
    void setLargeText(bool on);
    /// Logs the frame-time statistics every `seconds` (0: never) to the standard error.
    void setFrameLogInterval(int seconds);
    /// The status line's frame-time part (also logged): arena and plots, mean/p99/max.
    QString frameTimesText() const;

  public slots:
    /// Tools ▸ IR sensor calibration / Odometry calibration: opens the dialog (not blocking;
    /// one at a time) and returns it.
    IrCalibrationDialog* openIrCalibration();
    UmbmarkDialog* openUmbmark();
    /// File ▸ Re-filter recorded run…: opens the dialog (not blocking; one at a time).
    RefilterDialog* openRefilter();

  protected:
    void closeEvent(QCloseEvent* event) override;

  private:
    void buildDocks();
    void buildMenus();
    void updateStatus();
    void showRobotDock(QDockWidget* robot_dock);
    void restorePreferences();
    void savePreferences() const;

    Session& session_;
    ArenaView* arena_ = nullptr;
    PlotsPanel* plots_ = nullptr;
    ConfigPanel* config_ = nullptr;
    LessonPanel* lesson_ = nullptr;
    LessonActions* lesson_files_ = nullptr;
    CovarianceView* covariance_ = nullptr;
    RunToolBar* toolbar_ = nullptr;
    KeyboardDriver* keyboard_ = nullptr;
    KidnapAction* kidnap_ = nullptr;
    FileActions* files_ = nullptr;
    RobotStatusView* robot_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* robot_line_ = nullptr;
    QAction* reconnect_ = nullptr;
    QLabel* frames_ = nullptr;
    QAction* large_text_ = nullptr;
    QAction* frame_times_ = nullptr;
    QTimer* frame_log_ = nullptr;
};

}  // namespace legofeup::ui
