#pragma once

// main() for GUI suites: VTK needs the OpenGL 3.2 core surface format set before QApplication exists.
#include <QApplication>
#include <QSurfaceFormat>
#include <QtTest>

#define VSIM_GUI_TEST_MAIN(TestClass)                                                                                  \
    int main(int argc, char** argv)                                                                                    \
    {                                                                                                                  \
        QSurfaceFormat format;                                                                                         \
        format.setVersion(3, 2);                                                                                       \
        format.setProfile(QSurfaceFormat::CoreProfile);                                                                \
        format.setDepthBufferSize(24);                                                                                 \
        QSurfaceFormat::setDefaultFormat(format);                                                                      \
        QApplication application(argc, argv);                                                                          \
        QApplication::setOrganizationName("VascuSimTests");                                                            \
        TestClass test;                                                                                                \
        return QTest::qExec(&test, argc, argv);                                                                        \
    }
