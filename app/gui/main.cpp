// legofeup: the LegoFeup Lab desktop application.
#include <QApplication>
#include <QLabel>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QLabel label("LegoFeup Lab");
    label.show();
    return QApplication::exec();
}
