# The window: docks, menus, the run's toolbar and the NXT connect dialog (with its Bluetooth
# scan), keyboard driving, kidnapping the simulated robot, files, appearance, settings.
list(APPEND LEGOFEUP_UI_SOURCES
    window/app_settings.cpp
    window/appearance.cpp
    window/bluetooth_scan.cpp
    window/connect_dialog.cpp
    window/file_actions.cpp
    window/keyboard_driver.cpp
    window/kidnap_action.cpp
    window/main_window.cpp
    window/run_toolbar.cpp
    include/legofeup/ui/window/bluetooth_scan.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/connect_dialog.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/file_actions.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/keyboard_driver.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/kidnap_action.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/main_window.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/window/run_toolbar.hpp  # Q_OBJECT: listed for AUTOMOC
)
