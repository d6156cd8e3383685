#include "legofeup/ui/window/main_window.hpp"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QGuiApplication>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QStatusBar>
#include <QTimer>
#include <type_traits>

#include "legofeup/ui/arena/arena_view.hpp"
#include "legofeup/ui/calibration/ir_calibration_dialog.hpp"
#include "legofeup/ui/calibration/umbmark_dialog.hpp"
#include "legofeup/ui/lesson/lesson_actions.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/panels/config_panel.hpp"
#include "legofeup/ui/panels/covariance_view.hpp"
#include "legofeup/ui/panels/robot_status.hpp"
#include "legofeup/ui/plots/plots_panel.hpp"
#include "legofeup/ui/refilter/refilter_dialog.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/appearance.hpp"
#include "legofeup/ui/window/file_actions.hpp"
#include "legofeup/ui/window/keyboard_driver.hpp"
#include "legofeup/ui/window/kidnap_action.hpp"
#include "legofeup/ui/window/run_toolbar.hpp"

namespace legofeup::ui {
namespace {

QString stats_text(const char* name, const FrameStats& stats) {
    const FrameStats::Summary s = stats.summary();
    return QStringLiteral("%1 %2/%3/%4 ms")
        .arg(QLatin1String(name))
        .arg(s.mean_ms, 0, 'f', 1)
        .arg(s.p99_ms, 0, 'f', 1)
        .arg(s.max_ms, 0, 'f', 1);
}

QDockWidget* dock(QMainWindow* window, const QString& title, const QString& name, QWidget* content,
                  Qt::DockWidgetArea area) {
    auto* widget = new QDockWidget(title, window);
    widget->setObjectName(name);
    widget->setWidget(content);
    window->addDockWidget(area, widget);
    return widget;
}

/// The window's one dialog of this kind, brought to the front, or a new one (not blocking;
/// deleted when closed).
template <class Dialog>
Dialog* open_one(QMainWindow& window, const Session& session) {
    if (auto* open = window.findChild<Dialog*>()) {
        open->raise();
        open->activateWindow();
        return open;
    }
    auto* dialog = new Dialog(session, &window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    return dialog;
}

}  // namespace

MainWindow::MainWindow(Session& session, QWidget* parent) : QMainWindow(parent), session_(session) {
    setWindowTitle(tr("LegoFeup Lab"));
    setWindowIcon(QIcon(QStringLiteral(":/legofeup/legofeup-lab.svg")));
    buildDocks();
    buildMenus();
    restorePreferences();
    updateStatus();
}

MainWindow::~MainWindow() {
    qApp->removeEventFilter(keyboard_);
}

void MainWindow::buildDocks() {
    arena_ = new ArenaView(session_.history(), this);
    setCentralWidget(arena_);
    plots_ = new PlotsPanel(session_.history(), this);
    config_ = new ConfigPanel(session_, this);
    lesson_ = new LessonPanel(session_, this);
    covariance_ = new CovarianceView(session_.history(), this);
    robot_ = new RobotStatusView(session_, this);
    arena_->setEllipseConfidence(
        static_cast<EllipseConfidence>(std::clamp(preferences::kEllipseConfidence.read(), 0, 2)));
    arena_->setFollowRobot(preferences::kFollowRobot.read());
    plots_->setTimeWindow(preferences::kPlotWindow.read());
    plots_->setWantedTab(preferences::kPlotTab.read());
    toolbar_ = new RunToolBar(session_, this);
    addToolBar(Qt::TopToolBarArea, toolbar_);

    dock(this, tr("Lesson"), QStringLiteral("lessonDock"), lesson_, Qt::LeftDockWidgetArea);
    dock(this, tr("Covariance P"), QStringLiteral("covarianceDock"), covariance_,
         Qt::LeftDockWidgetArea);
    dock(this, tr("Configuration"), QStringLiteral("configDock"), config_, Qt::RightDockWidgetArea);
    // Below the configuration; shown with an NXT (and whenever asked for, View ▸ Robot).
    auto* robot_scroll = new QScrollArea(this);  // a long failure reason scrolls, never cut
    robot_scroll->setWidget(robot_);
    robot_scroll->setWidgetResizable(true);
    robot_scroll->setFrameShape(QFrame::NoFrame);
    QDockWidget* robot_dock =
        dock(this, tr("Robot"), QStringLiteral("robotDock"), robot_scroll, Qt::RightDockWidgetArea);
    robot_dock->setVisible(session_.linkChoice().kind == LinkKind::Nxt);
    dock(this, tr("Plots"), QStringLiteral("plotsDock"), plots_, Qt::BottomDockWidgetArea);
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);

    // The run's samples reach every view from one signal: one batch, one repaint each.
    const auto wire = [this](auto* view) {
        using View = std::remove_pointer_t<decltype(view)>;
        connect(&session_, &Session::historyRestarted, view, &View::historyRestarted);
        connect(&session_, &Session::samplesAppended, view, &View::samplesAppended);
    };
    wire(arena_);
    wire(plots_);
    wire(covariance_);
    connect(&session_, &Session::samplesAppended, this, &MainWindow::updateStatus);
    connect(&session_, &Session::phaseChanged, this, &MainWindow::updateStatus);
    connect(&session_, &Session::samplesAppended, robot_, &RobotStatusView::refresh);
    connect(&session_, &Session::phaseChanged, robot_, &RobotStatusView::refresh);
    connect(&session_, &Session::linkChoiceChanged, this, [this, robot_dock] {
        robot_->refresh();
        if (session_.linkChoice().kind == LinkKind::Nxt) {
            showRobotDock(robot_dock);
        }
    });
    connect(&session_, &Session::problem, this,
            [this](const QString& message) { statusBar()->showMessage(message, 15000); });

    keyboard_ = new KeyboardDriver(session_, this);
    qApp->installEventFilter(keyboard_);
    kidnap_ = new KidnapAction(session_, *arena_, this);
    toolbar_->addRunAction(kidnap_->action());
    files_ = new FileActions(session_, *plots_, this);
    lesson_files_ = new LessonActions(*lesson_, this);
    const auto show_note = [this](const QString& note) { statusBar()->showMessage(note, 10000); };
    connect(files_, &FileActions::done, this, show_note);
    connect(kidnap_, &KidnapAction::done, this, show_note);
    connect(lesson_files_, &LessonActions::done, this, show_note);
    connect(lesson_, &LessonPanel::note, this, show_note);
    connect(lesson_, &LessonPanel::openLessonRequested, lesson_files_, &LessonActions::openLesson);

    robot_line_ = new QLabel(this);
    robot_line_->setObjectName(QStringLiteral("robotLine"));
    robot_line_->setVisible(false);
    statusBar()->addPermanentWidget(robot_line_);
    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("runStatus"));
    statusBar()->addPermanentWidget(status_);
    frames_ = new QLabel(this);
    frames_->setVisible(false);
    statusBar()->addPermanentWidget(frames_);
    frame_log_ = new QTimer(this);
    connect(frame_log_, &QTimer::timeout, this,
            [this] { qInfo("frame times (mean/p99/max): %s", qPrintable(frameTimesText())); });
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Load configuration…"), QKeySequence::Open, files_,
                    &FileActions::loadConfig);
    file->addAction(tr("&Save configuration…"), QKeySequence::Save, files_,
                    &FileActions::saveConfig);
    file->addSeparator();
    file->addAction(tr("Open &lesson…"), lesson_files_, &LessonActions::openLesson);
    file->addAction(tr("Open a&nswers…"), lesson_files_, &LessonActions::openAnswers);
    file->addAction(tr("Save &answers…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
                    lesson_files_, &LessonActions::saveAnswers);
    file->addAction(tr("&Export report…"), QKeySequence(Qt::CTRL | Qt::Key_E), lesson_files_,
                    &LessonActions::exportReport);
    file->addSeparator();
    QAction* record = file->addAction(tr("&Record runs…"));
    record->setToolTip(
        tr("Records every run into a folder: trace.csv and run.log, the run log "
           "File ▸ Re-filter replays"));
    record->setCheckable(true);
    connect(record, &QAction::toggled, files_, &FileActions::setRecording);
    connect(files_, &FileActions::recordingChanged, this, &MainWindow::updateStatus);
    connect(files_, &FileActions::recordingChanged, record, [record](bool on) {
        const QSignalBlocker blocker(record);
        record->setChecked(on);
    });
    file->addAction(tr("Export &plots…"), files_, &FileActions::exportPlots);
    file->addAction(tr("Export &trace (CSV)…"), files_, &FileActions::exportTrace);
    file->addAction(tr("Re-&filter recorded run…"), this, &MainWindow::openRefilter);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* run = menuBar()->addMenu(tr("&Run"));
    run->addAction(toolbar_->startAction());
    run->addAction(toolbar_->pauseAction());
    run->addAction(toolbar_->stopAction());
    run->addAction(toolbar_->resetAction());
    run->addAction(kidnap_->action());
    run->addSeparator();
    reconnect_ = run->addAction(tr("Re&connect"));
    reconnect_->setObjectName(QStringLiteral("reconnectAction"));
    reconnect_->setToolTip(tr("Connect again with the same robot after a failure"));
    connect(reconnect_, &QAction::triggered, &session_, &Session::start);
    run->addAction(toolbar_->connectAction());
    run->addSeparator();
    QAction* manual = run->addAction(tr("Drive with the &keyboard"));
    manual->setCheckable(true);
    manual->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    connect(manual, &QAction::toggled, &session_, &Session::setManualDriving);
    connect(&session_, &Session::manualDrivingChanged, manual, &QAction::setChecked);

    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    tools->addAction(toolbar_->connectAction());
    tools->addSeparator();
    tools->addAction(tr("&IR sensor calibration…"), this, &MainWindow::openIrCalibration);
    tools->addAction(tr("&Odometry calibration (UMBmark)…"), this, &MainWindow::openUmbmark);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QMenu* confidence = view->addMenu(tr("Covariance &ellipse"));
    auto* confidence_group = new QActionGroup(this);
    const std::array<std::pair<QString, EllipseConfidence>, 3> levels = {{
        {tr("1σ (39.3 % in 2-D; the paper's 68.2 % is 1-D)"), EllipseConfidence::OneSigma},
        {tr("95 %"), EllipseConfidence::Percent95},
        {tr("99 %"), EllipseConfidence::Percent99},
    }};
    for (const auto& [label, level] : levels) {
        QAction* action = confidence->addAction(label);
        action->setCheckable(true);
        action->setChecked(level == arena_->ellipseConfidence());
        confidence_group->addAction(action);
        connect(action, &QAction::triggered, this, [this, level = level] {
            arena_->setEllipseConfidence(level);
            preferences::kEllipseConfidence.write(static_cast<int>(level));
        });
    }
    QAction* follow = view->addAction(tr("&Follow the robot"));
    follow->setCheckable(true);
    follow->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F));
    follow->setChecked(arena_->followRobot());
    connect(follow, &QAction::toggled, arena_, &ArenaView::setFollowRobot);
    connect(arena_, &ArenaView::followRobotChanged, follow, &QAction::setChecked);
    QAction* legend = view->addAction(tr("Arena &legend"));
    legend->setCheckable(true);
    legend->setChecked(arena_->showLegend());
    connect(legend, &QAction::toggled, arena_, &ArenaView::setShowLegend);
    view->addAction(tr("Zoom &in"), QKeySequence::ZoomIn, arena_, &ArenaView::zoomIn);
    view->addAction(tr("Zoom &out"), QKeySequence::ZoomOut, arena_, &ArenaView::zoomOut);
    view->addAction(tr("Fit the &arena"), QKeySequence(Qt::CTRL | Qt::Key_0), arena_,
                    &ArenaView::fitArena);
    view->addSeparator();
    large_text_ = view->addAction(tr("&Large text (projector)"));
    large_text_->setCheckable(true);
    large_text_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    connect(large_text_, &QAction::toggled, this, &MainWindow::setLargeText);
    QMenu* theme = view->addMenu(tr("&Theme"));
    auto* theme_group = new QActionGroup(this);
    for (const Theme choice : {Theme::System, Theme::Light, Theme::Dark}) {
        const QString name = theme_name(choice);
        QAction* action = theme->addAction(name.left(1).toUpper() + name.mid(1));
        action->setCheckable(true);
        action->setChecked(theme_from_name(preferences::kTheme.read()) == choice);
        theme_group->addAction(action);
        connect(action, &QAction::triggered, this, [this, choice] {
            preferences::kTheme.write(theme_name(choice));
            apply_appearance(*qApp, choice, large_text_->isChecked() ? kLargeTextScale : 1.0);
        });
    }
    frame_times_ = view->addAction(tr("Frame &times"));
    frame_times_->setCheckable(true);
    frame_times_->setShortcut(Qt::Key_F12);
    connect(frame_times_, &QAction::toggled, this, [this](bool on) {
        arena_->setShowFrameTimes(on);
        frames_->setVisible(on);
        updateStatus();
    });
    view->addSeparator();
    for (QDockWidget* widget : findChildren<QDockWidget*>()) {
        view->addAction(widget->toggleViewAction());
    }

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Keyboard driving"), this, [this] {
        QMessageBox::information(
            this, tr("Keyboard driving"),
            tr("Turn the path controller off (toolbar, or Run ▸ Drive with the keyboard).\n\n"
               "↑ / W  forward at V_ref      ↓ / S  backwards\n"
               "← / A  turn left at W_ref     → / D  turn right\n"
               "Space  stop\n\nKeys combine: ↑ and ← drive a left curve."));
    });
    help->addAction(tr("&About LegoFeup Lab"), this, [this] {
        QMessageBox::about(this, tr("About LegoFeup Lab"),
                           tr("<b>LegoFeup Lab</b> %1<br>Mobile-robot localisation with the "
                              "Extended Kalman Filter, after Pinto, Moreira &amp; Matos (2012).")
                               .arg(QApplication::applicationVersion()));
    });
}

void MainWindow::setLargeText(bool on) {
    const QSignalBlocker blocker(large_text_);
    large_text_->setChecked(on);
    const double scale = on ? kLargeTextScale : 1.0;
    // The views draw with their widget's font, which follows the application's: scaling it
    // is enough for their text (a text scale of their own would scale twice).
    apply_appearance(*qApp, theme_from_name(preferences::kTheme.read()), scale);
    arena_->setTextScale(1.0);
    plots_->setTextScale(1.0);
    preferences::kLargeText.write(on);
}

void MainWindow::setFrameLogInterval(int seconds) {
    if (seconds > 0) {
        frame_log_->start(seconds * 1000);
    } else {
        frame_log_->stop();
    }
}

QString MainWindow::frameTimesText() const {
    return stats_text("arena", arena_->frameStats()) + QStringLiteral(" · ")
           + stats_text("plots", plots_->frameStats());
}

void MainWindow::showRobotDock(QDockWidget* robot_dock) {
    const bool was_visible = robot_dock->isVisible();
    robot_dock->show();
    robot_dock->raise();
    if (!was_visible) {
        // Tall enough for its rows (the configuration above it scrolls anyway).
        resizeDocks({robot_dock}, {robot_->sizeHint().height() + 40}, Qt::Vertical);
    }
}

IrCalibrationDialog* MainWindow::openIrCalibration() {
    return open_one<IrCalibrationDialog>(*this, session_);
}

UmbmarkDialog* MainWindow::openUmbmark() {
    return open_one<UmbmarkDialog>(*this, session_);
}

RefilterDialog* MainWindow::openRefilter() {
    return open_one<RefilterDialog>(*this, session_);
}

void MainWindow::updateStatus() {
    const LiveRunStatus& status = session_.status();
    const QString robot = robot_status_line(session_.phase(), status);
    robot_line_->setText(robot);
    robot_line_->setVisible(!robot.isEmpty());
    reconnect_->setEnabled(session_.phase() == RunPhase::Failed);
    QString text = phase_text(session_.phase());
    if (session_.phase() != RunPhase::Idle) {
        text += tr(" · t = %1 s · step %2").arg(status.time, 0, 'f', 1).arg(status.steps);
        if (status.frames_missing > 0) {
            text += tr(" · %n frame(s) missing", nullptr, static_cast<int>(status.frames_missing));
        }
    }
    if (session_.manualDriving()) {
        text += tr(" · keyboard driving");
    }
    if (!session_.recordingDirectory().isEmpty()) {
        const QString file = QFileInfo(session_.recordingFile()).fileName();
        text += file.isEmpty() ? tr(" · ● recording") : tr(" · ● recording %1").arg(file);
    }
    status_->setText(text);
    if (frames_->isVisible()) {
        frames_->setText(frameTimesText());
    }
}

void MainWindow::restorePreferences() {
    if (!restoreGeometry(preferences::kWindowGeometry.read())) {
        // First start: most of the screen, the arena large, the plots below it.
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        resize(screen.size() * 0.92);
        resizeDocks({findChild<QDockWidget*>(QStringLiteral("plotsDock"))},
                    {static_cast<int>(screen.height() * 0.36)}, Qt::Vertical);
        resizeDocks(
            {findChild<QDockWidget*>(QStringLiteral("lessonDock")),
             findChild<QDockWidget*>(QStringLiteral("configDock"))},
            {static_cast<int>(screen.width() * 0.24), static_cast<int>(screen.width() * 0.22)},
            Qt::Horizontal);
        // The lesson's step and questions get most of the left column; P needs a few lines.
        resizeDocks(
            {findChild<QDockWidget*>(QStringLiteral("lessonDock")),
             findChild<QDockWidget*>(QStringLiteral("covarianceDock"))},
            {static_cast<int>(screen.height() * 0.7), static_cast<int>(screen.height() * 0.2)},
            Qt::Vertical);
    }
    restoreState(preferences::kWindowState.read());
    frame_times_->setChecked(preferences::kShowFrameTimes.read());
    if (preferences::kLargeText.read()) {
        setLargeText(true);
    }
}

void MainWindow::savePreferences() const {
    preferences::kWindowGeometry.write(saveGeometry());
    preferences::kWindowState.write(saveState());
    preferences::kFollowRobot.write(arena_->followRobot());
    preferences::kPlotWindow.write(plots_->timeWindow());
    preferences::kPlotTab.write(plots_->wantedTab());
    preferences::kShowFrameTimes.write(frame_times_->isChecked());
    save_link_choice(session_.linkChoice());
    preferences::kExperiment.write(lesson_->currentStep());
    lesson_->saveAnswersNow();
    QDir().mkpath(QFileInfo(last_config_path()).path());
    session_.saveConfig(last_config_path());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    savePreferences();
    session_.stop();
    event->accept();
}

}  // namespace legofeup::ui
