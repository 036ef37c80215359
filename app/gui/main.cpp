// vascusim: the workstation. `vascusim [study.vsim]` opens a study; `vascusim --demo` opens the built-in demo
// study (written on first use under ~/.local/share/VascuSim).
#include "Languages.h"
#include "MainWindow.h"
#include "PacsNodes.h"
#include "vsim/app/DemoStudy.h"
#include "vsim/dicom/PacsClient.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QProgressDialog>
#include <QSurfaceFormat>

#include <iostream>

int main(int argc, char** argv)
{
    // VTK's OpenGL2 backend needs a 3.2 core profile with a depth buffer, set before QApplication exists.
    QSurfaceFormat format;
    format.setVersion(3, 2);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    QSurfaceFormat::setDefaultFormat(format);
    vsim::dicom::prepareDicomNetworking(); // before any thread reads the environment

    QApplication application(argc, argv);
    QApplication::setOrganizationName("VascuSim");
    QApplication::setApplicationName("VascuSim");
    vsim::gui::installLanguage(vsim::gui::chosenLanguage());
    vsim::gui::applySavedUidRoot();

    QCommandLineParser parser;
    parser.setApplicationDescription("VascuSim clinical planning workstation");
    parser.addHelpOption();
    parser.addOption({"demo", "Open the built-in demo study (generated on first use)."});
    parser.addPositionalArgument("study", "A study bundle (folder ending in .vsim) to open.");
    parser.process(application);

    auto* window = new vsim::gui::MainWindow();
    window->show();
    if (parser.isSet("demo"))
    {
        try
        {
            // First use writes the full-size aaa phantom (some seconds): a modal progress dialog meanwhile.
            QProgressDialog writing(QObject::tr("Writing the demo study (aaa phantom)..."), QString(), 0, 100, window);
            writing.setWindowModality(Qt::WindowModal);
            writing.setMinimumDuration(500);
            const vsim::Progress progress(
                [&writing](double fraction, const std::string&) { writing.setValue(int(fraction * 100.0)); }, {});
            const auto bundle = vsim::app::ensureDemoStudy(vsim::app::defaultDemoStudyPath(), progress);
            writing.setValue(100);
            window->openStudy(QString::fromStdString(bundle.string()));
        }
        catch (const std::exception& error)
        {
            std::cerr << "cannot write the demo study: " << error.what() << "\n";
            return 1;
        }
    }
    else if (!parser.positionalArguments().isEmpty())
        window->openStudy(parser.positionalArguments().constFirst());
    return application.exec();
}
