// Flow > Blood Flow Parameters' "Automatic" ticks (ParameterForm.h): the SPH solver parameters the blood flow and the
// needle injection choose for the vessel start ticked; unticked, the field's value is given to the run even where it
// equals the solver's default (before, a value equal to the default read as "not given" and the pipeline's choice
// replaced it: the stenosis pipeline's Courant number 0.1 could not be set back to the solver's 0.2).

#include "GuiTestMain.h"
#include "ParameterForm.h"
#include "vsim/app/BloodFlowPipeline.h"
#include "vsim/app/InjectionPipeline.h"
#include "vsim/sim/sph/SphSolver.h"

#include <QCheckBox>
#include <QDoubleSpinBox>

#include <algorithm>

using namespace vsim;

namespace {

bool contains(const std::vector<std::string>& keys, const std::string& key)
{
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

} // namespace

class AutomaticParametersTest : public QObject
{
    Q_OBJECT
private slots:
    void theWindowStartsWithEveryChoiceAutomatic()
    {
        gui::MainWindow window;
        const gui::AutomaticParameters& automatic = window.sphAutomatic();
        for (const auto* chosen : {&app::bloodFlowChosenParameters(), &app::injectionChosenParameters()})
            for (const std::string& key : *chosen)
                QVERIFY2(contains(automatic.keys, key) && automatic.ticked.count(key), key.c_str());
        QCOMPARE(automatic.ticked.size(), automatic.keys.size());
        QVERIFY(!contains(automatic.keys, "viscosity_pa_s")); // not chosen: always as the form shows it
    }

    void anUntickedValueIsGivenEvenAtItsDefault()
    {
        const ParameterSet solver(sim::sph::sphParameters());
        gui::AutomaticParameters automatic;
        automatic.keys = app::bloodFlowChosenParameters();
        automatic.ticked.insert(automatic.keys.begin(), automatic.keys.end());
        gui::ParameterForm form(solver, automatic);
        auto* cfl = form.findChild<QDoubleSpinBox*>("cfl");
        auto* tick = form.findChild<QCheckBox*>("cfl_automatic");
        QVERIFY(cfl && tick);
        QVERIFY(tick->isChecked() && !cfl->isEnabled());
        QVERIFY(!form.findChild<QCheckBox*>("viscosity_pa_s_automatic"));

        const ParameterSet setupForm(app::bloodFlowSetupParameters());
        app::BloodFlowSetup chosen = app::bloodFlowSetupFrom(setupForm, form.values(), form.automatic());
        QVERIFY(!contains(chosen.given, "cfl") && !contains(chosen.given, "sound_speed_m_s"));
        QVERIFY(contains(chosen.given, "viscosity_pa_s"));

        // Unticked at the solver's own default: given, the value as shown.
        tick->setChecked(false);
        QVERIFY(cfl->isEnabled());
        QCOMPARE(cfl->value(), solver.get("cfl"));
        const app::BloodFlowSetup given = app::bloodFlowSetupFrom(setupForm, form.values(), form.automatic());
        QVERIFY(contains(given.given, "cfl") && !contains(given.given, "sound_speed_m_s"));
        QCOMPARE(given.parameters.get("cfl"), solver.get("cfl"));

        // Ticked again: the default shown, the run chooses; Restore Defaults ticks every one.
        cfl->setValue(0.05);
        tick->setChecked(true);
        QCOMPARE(cfl->value(), solver.get("cfl"));
        tick->setChecked(false);
        form.resetToDefaults();
        QVERIFY(tick->isChecked() && form.automatic() == automatic.ticked);
    }

    void theInjectionTakesTheSameTicks()
    {
        const ParameterSet solver(sim::sph::sphParameters());
        const ParameterSet setupForm(app::injectionSetupParameters());
        std::set<std::string> ticked(app::injectionChosenParameters().begin(), app::injectionChosenParameters().end());
        QVERIFY(!contains(app::injectionSetupFrom(setupForm, solver, ticked).given, "free_surface"));
        ticked.erase("free_surface"); // the solver's default (0): a closed vessel, given as such
        const app::InjectionSetup setup = app::injectionSetupFrom(setupForm, solver, ticked);
        QVERIFY(contains(setup.given, "free_surface") && !contains(setup.given, "fluid_tension"));
    }
};

VSIM_GUI_TEST_MAIN(AutomaticParametersTest)
#include "tst_automatic_parameters.moc"
