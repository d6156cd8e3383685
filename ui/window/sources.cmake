# The window: docks, menus, the run's toolbar and the NXT connect dialog (with its Bluetooth
# scan; below), keyboard driving, kidnapping the simulated robot, files, appearance, settings;
# the command line, the display check and what the window starts with.
list(APPEND LEGOFEUP_UI_SOURCES
    window/app_settings.cpp
    window/appearance.cpp
    window/at_run_time.cpp
    window/command_line.cpp
    window/display_check.cpp
    window/file_actions.cpp
    window/keyboard_driver.cpp
    window/kidnap_action.cpp
    window/main_window.cpp
    window/run_toolbar.cpp
    window/start_up.cpp
    include/legofeup/ui/window/file_actions.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/keyboard_driver.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/kidnap_action.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/main_window.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/run_toolbar.hpp  # Q_OBJECT: listed for AUTOMOC
)
# The NXT connect dialog and its Bluetooth scan (Qt Bluetooth), which the toolbar opens; in a
# build without the NXT (LEGOFEUP_WITH_NXT=OFF), the toolbar's file that has no dialog.
if(LEGOFEUP_WITH_NXT)
    list(APPEND LEGOFEUP_UI_SOURCES
        window/bluetooth_scan.cpp
        window/connect_dialog.cpp
        window/run_toolbar_nxt.cpp
        include/legofeup/ui/window/bluetooth_scan.hpp  # Q_OBJECT: listed for AUTOMOC
        include/legofeup/ui/window/connect_dialog.hpp  # Q_OBJECT: listed for AUTOMOC
    )
else()
    list(APPEND LEGOFEUP_UI_SOURCES window/run_toolbar_no_nxt.cpp)
endif()
