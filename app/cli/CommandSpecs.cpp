// The declarations of vascusim-cli's commands: options, positional arguments and usage (CommandLine.h).

#include "BloodFlowCommand.h"
#include "SmokeCommand.h"
#include "CommandLine.h"
#include "DemoCommand.h"
#include "NetworkCommands.h"
#include "PacsCommand.h"
#include "ReportCommand.h"
#include "ValidateCommand.h"
#include "WallCommands.h"

namespace vsim::cli {
namespace {

using Arity = OptionSpec::Arity;

OptionSpec value(const std::string& name) { return {name, Arity::Value}; }
OptionSpec flag(const std::string& name) { return {name, Arity::Flag}; }
OptionSpec repeatable(const std::string& name) { return {name, Arity::Repeatable}; }
OptionSpec required(const std::string& name) { return {name, Arity::Value, true}; }

/// Every command that writes into a study waits for its lock this long (default 0: refuse at once).
const OptionSpec kWait = value("wait");
const OptionSpec kParam = repeatable("param");
const OptionSpec kStudy = required("study");
/// The organisation's DICOM UID root for the objects a command makes (runCommandLine applies it).
const OptionSpec kUidRoot = value("uid-root");

/// The PACS node's options (every pacs command) and then `more`.
std::vector<OptionSpec> pacsNodeAnd(std::vector<OptionSpec> more)
{
    std::vector<OptionSpec> options{required("aet"),  required("host"),  required("port"),    value("calling-aet"),
                                    value("timeout"), flag("tls"),       value("tls-trusted"), value("tls-cert"),
                                    value("tls-key")};
    options.insert(options.end(), more.begin(), more.end());
    return options;
}

std::vector<CommandSpec> declareCommands()
{
    return {
        {"info", 1, 1, {}, "info <study.vsim>\n    the study's metadata and artifacts as JSON (works while another process writes it)",
         [](const Arguments& a, const Progress&) { return printStudyInfo(a); }},
        {"parameters", 0, 1, {flag("json")},
         "parameters [TABLE] [--json]\n"
         "    every parameter that --param key=value and the GUI's forms take, by table (segmentation, skeleton,\n"
         "    fem, sph, ...): default, range, unit and meaning",
         [](const Arguments& a, const Progress&) { return printParameters(a); }},
        {"import", 1, 1, {value("study"), value("series"), flag("list"), value("memory-limit-mb"), value("rescale"),
                           flag("as-label"), value("label-value"), value("image"), kWait},
         "import <dir|DICOMDIR|file> --study <study.vsim> [--series KEY] [--list] [--memory-limit-mb N]\n"
         "       [--rescale SLOPE,INTERCEPT] [--as-label [--label-value 1] [--image ID]] [--wait s]\n"
         "    add a DICOM series (the CT with most slices unless --series) or a NIfTI / NRRD / MetaImage volume;\n"
         "    creates the study in a new or empty folder; values must read as CT in HU (any CT in HU does, a crop\n"
         "    without air too), else give the rescale HU = SLOPE x stored + INTERCEPT; --as-label adds a mask as a\n"
         "    label on the study's image grid (a NIfTI / NRRD / MetaImage file, a DICOM SEG or a DICOM mask series;\n"
         "    its own labels, a mask of one value as label 1, or every nonzero voxel as --label-value), refused when the\n"
         "    grids do not match; --list prints the series found as JSON and imports nothing",
         importIntoStudy},
        {"phantom", 1, 1,
         {required("out"), value("size"), value("spacing"), value("noise"), value("seed"), value("transfer-syntax"),
          value("max-diameter"), value("stenosis"), value("blur"), value("style"), value("psf-fwhm"), flag("enhanced"),
          value("vessel-diameter"), value("stenosis-length")},
         "phantom <aaa|stenosis|hepatic-tree|bifurcation> --out <dir> [--style patient|analytic] [--size 512x512x400]\n"
         "        [--spacing 0.7,0.7,1.0] [--noise HU] [--seed 1] [--psf-fwhm mm] [--blur mm] [--max-diameter 55]\n"
         "        [--stenosis 50[,B]] [--vessel-diameter 6] [--stenosis-length mm]\n"
         "        [--transfer-syntax explicit-le|implicit-le|jpeg-lossless|jpeg-ls|rle] [--enhanced]\n"
         "    write a CT phantom series (<dir>/dicom) with truth.json and truth-label.nrrd into a new or empty folder;\n"
         "    patient (default; bifurcation: analytic): anatomy, PSF, correlated noise, thrombus, calcium, the scanner\n"
         "    drawn from the seed unless --psf-fwhm / --noise are given; analytic: the exact partial-volume model\n"
         "    (--blur sigma, --noise 20) for tests that need an exact case; the patient-style stenosis takes its\n"
         "    lumen diameter, the stenosis's length (else drawn, 20-28 mm) and a second, milder blockage B 12 mm\n"
         "    past the first (the thesis's hand case)",
         writePhantomSeries},
        {"segment", 0, 0,
         {kStudy, value("image"), repeatable("seed"), value("target"), repeatable("exclude"), repeatable("stop"),
          value("max-length"), kParam, kWait},
         "segment --study <study.vsim> [--image ID] [--target aorta|hepatic|all --seed x,y,z ... [--exclude x,y,z ...]\n"
         "        [--stop x,y,z,nx,ny,nz ...] [--max-length mm]] [--seed x,y,z] [--param key=value ...] [--wait s]\n"
         "    with --target: the vessel grown from the include points (--seed, mm, repeatable), competing with the\n"
         "    exclude points, not past the stop planes (the side the normal points to) nor the path length, leaks cut\n"
         "    where the cross-section jumps; without: the contrast-filled vessels from one seed (automatic unless given)",
         segmentStudy},
        {"sac", 0, 0, {kStudy, value("label"), value("image"), value("wall-thickness"), kWait},
         "sac --study <study.vsim> [--label ID] [--image ID] [--wall-thickness 1.8mm] [--wait s]\n"
         "    the AAA sac of an aortic lumen label: outer contour, thrombus and an assumed-thickness wall as a label\n"
         "    (1 lumen, 4 thrombus, 5 wall); the SVS maximum outer diameter, the sac volume, the neck, each with its\n"
         "    definition",
         sacStudy},
        {"surface", 0, 0, {kStudy, value("label"), value("target-vertices"), value("stl"), flag("overwrite"), kParam, kWait},
         "surface --study <study.vsim> [--label ID] [--target-vertices N] [--stl FILE [--overwrite]] [--param key=value ...]\n"
         "    the lumen surface of the newest vessel label (VTP in the study; STL when asked)",
         surfaceStudy},
        {"skeleton", 0, 0, {kStudy, value("label"), kParam, kWait},
         "skeleton --study <study.vsim> [--label ID] [--param key=value ...] [--wait s]\n"
         "    unit-width skeleton graph (thinning + VDSM) of the newest label",
         skeletonStudy},
        {"centerline", 0, 0, {kStudy, value("skeleton"), value("label"), value("from"), value("to"), kParam, kWait},
         "centerline --study <study.vsim> [--skeleton ID] [--label ID] [--from NODE --to NODE] [--param key=value ...]\n"
         "    B-spline centerlines (fast marching + minimal paths) of every skeleton edge, or of one path",
         centerlineStudy},
        {"measure", 0, 0, {kStudy, value("centerlines"), value("label"), value("json"), flag("overwrite"), kParam},
         "measure --study <study.vsim> [--centerlines ID] [--label ID] [--json FILE [--overwrite]] [--param key=value ...]\n"
         "    cross-sections, lengths, radii, maximum diameter, stenosis (reads the study only)",
         measureStudy},
        {"export-label", 0, 0, {kStudy, value("label"), required("out"), flag("overwrite"), kUidRoot},
         "export-label --study <study.vsim> [--label ID] --out FILE.dcm [--overwrite] [--uid-root ROOT]\n"
         "    a label as a DICOM SEG (one segment per value: lumen 1, a sac's thrombus 4 and wall 5) in the CT's\n"
         "    study and frame of reference, for PACS, 3D Slicer or a vendor workstation (reads the study only)",
         exportLabelFromStudy},
        {"segment-organ", 0, 0, {kStudy, value("image"), repeatable("seed"), value("organ"), value("within"), kParam, kWait},
         "segment-organ --study <study.vsim> --seed x,y,z [--seed ...] [--organ liver|tumour|NAME] [--within LIVER]\n"
         "              [--image ID] [--param key=value ...] [--wait s]\n"
         "    the organ as a label grown from points inside it (its own intensity window, bridges to touching organs\n"
         "    cut, small gaps closed): the liver and tumour labels for simulate network --liver-label --tumour-label;\n"
         "    with --within, a lesion in that liver label (its boundary where the tissue leaves the parenchyma's range)",
         segmentOrgan},
        {"rename-segment", 0, 0, {kStudy, value("centerlines"), required("segment"), required("name"), kWait},
         "rename-segment --study <study.vsim> [--centerlines ID] --segment N --name TEXT [--wait s]\n"
         "    name a centerline segment (N as `measure` lists it) where the automatic anatomical name is wrong or\n"
         "    \"unnamed\"; kept with the study and used by measure, the workstation and the report",
         renameSegmentInStudy},
        {"mesh wall", 1, 1,
         {kStudy, value("label"), value("centerlines"), value("thickness"), value("target-vertices"), flag("thrombus"),
          kWait},
         "mesh wall --study <study.vsim> [--label ID] [--centerlines ID] [--thickness 1.5mm] [--target-vertices 3000]\n"
         "          [--thrombus]\n"
         "    tetrahedral vessel wall (one layer) around the lumen, opened at the centerline ends (fixed sets); the\n"
         "    thickness an assumption (1.5 mm: the uniform AAA wall of Raghavan et al. 2000, J Vasc Surg 31:760);\n"
         "    --thrombus: the intraluminal thrombus of the study's AAA sac (vascusim-cli sac) as its own layer inside\n"
         "    the sac (simulate fem's default wall model 1 takes it; the linear model 0 refuses it)",
         meshWall},
        {"mesh sheet", 1, 1,
         {kStudy, value("width"), value("length"), value("thickness"), value("cell"), kWait},
         "mesh sheet --study <study.vsim> [--width 40mm] [--length 40mm] [--thickness 0.5mm] [--cell 1mm]\n"
         "    a thin cloth-type sheet (thesis 4.7.3), edges across x fixed",
         meshWall},
        {"mesh import", 2, 2,
         {kStudy, value("pressure-array"), value("fixed-array"), value("lumen-point"), flag("fix-open-ends"), kWait},
         "mesh import <mesh.vtu> --study <study.vsim> (--pressure-array NAME | --lumen-point x,y,z)\n"
         "            (--fixed-array NAME | --fix-open-ends)\n"
         "    a tetrahedral mesh from outside as a wall: the pressure faces from a cell-data array of the boundary\n"
         "    faces or the inner surface reached from a point in the lumen, the fixed nodes from a point-data array\n"
         "    or the mesh's open boundary loops",
         meshWall},
        {"simulate fem", 1, 1,
         {kStudy, required("protocol"), value("mesh"), value("centerlines"), value("backend"), kParam, value("out"), kWait},
         "simulate fem --study <study.vsim> --protocol thesis-rupture|physiological [--mesh ID] [--backend auto|cpu|cuda]\n"
         "             [--param key=value ...] [--out DIR]\n"
         "    wall mechanics: the last frame (stresses, rupture index) and the metrics into the study; the frame\n"
         "    series (.vtu, series.pvd, metrics.json) to DIR (new, empty, or an earlier run folder)",
         simulateFem},
        {"simulate network", 1, 1,
         {kStudy, required("tip"), value("rate"), value("tip-pressure"), value("void-fraction"), value("tumour"),
          value("tumour-label"), value("tumour-value"), value("liver-label"), value("liver-value"), repeatable("control"),
          value("network"), value("inlet"), repeatable("add-feeder"), repeatable("remove-feeder"),
          value("default-outlets"), value("centerlines"), kParam, value("out"), kWait},
         "simulate network --study <study.vsim> --tip NODE|x,y,z|root [--rate 2ml/min|g/min | --tip-pressure mmHg]\n"
         "                 [--void-fraction 0.1] [--tumour x,y,z,r | --tumour-label ID [--tumour-value N]]\n"
         "                 [--liver-label ID [--liver-value N]] [--add-feeder SEGMENT ...] [--remove-feeder SEGMENT ...]\n"
         "                 [--inlet NAME|SEGMENT|x,y,z] [--control x,y,z ...] [--network FILE [--default-outlets murray]]\n"
         "                 [--param key=value ...] [--out DIR]\n"
         "    drug delivery (arterial blood carrying the two-phase drug through a conical Hagen-Poiseuille network):\n"
         "    flow split, the catheter (wedge, reflux), filling, control points two-phase vs liquid, tumour share and\n"
         "    the best tip positions; with a liver label: perfusion territories, the tip's perfused territory, the\n"
         "    lesions' coverage grade (A/B/C, 5 / 10 mm margin) and feeders, tips ranked by coverage. --inlet: blood\n"
         "    enters through that segment (e.g. \"celiac trunk\", \"common hepatic artery\", or the one nearest a\n"
         "    point; default the largest end) and the tree beyond it is modelled (--tip NODE and every node and\n"
         "    segment number are then the kept tree's, as the run reports them); --add-feeder and\n"
         "    --remove-feeder correct the feeders found (segment numbers as feeders.csv lists them)",
         simulateNetwork},
        {"simulate sph", 1, 1,
         {kStudy, value("inlet"), value("outlet"), value("waveform"), value("profile"), value("spacing"), value("until"),
          value("ramp"), value("void-fraction"), value("compare"), value("frames"), value("backend"), value("centerlines"),
          kParam, value("out"), kWait},
         "simulate sph --study <study.vsim> [--inlet 5ml/s|0.3m/s|90mmHg[@NODE]] [--outlet 0mmHg] [--waveform FILE]\n"
         "             [--profile parabolic|plug] [--spacing 0.5mm] [--until 0.2s] [--ramp 0.05s] [--void-fraction 0]\n"
         "             [--compare 6mm] [--frames 20] [--backend auto|cpu|cuda] [--param key=value ...] [--out DIR]\n"
         "    blood flow through the vessels of the study's centerlines (weakly compressible SPH on the lumen label):\n"
         "    the inlet at the largest vessel's end (or NODE; default a mean 0.2 m/s, parabolic, ramped up from rest),\n"
         "    pressure outlets at the other ends (--outlet: their gauge pressure, the level every pressure is reported\n"
         "    at); a Run of particle frames (speed, velocity, pressure) and, along the narrowest inlet-outlet path, the\n"
         "    stenosis figures (peak and mean velocity ratios at --compare upstream and\n"
         "    downstream of the throat, the pressure drop and ratio) averaged over the settled second half of the run\n"
         "    (the last waveform cycle); the frame series to DIR. Defaults: 5 particles per inlet radius, a sound speed\n"
         "    of 10 times the expected peak speed and at least what keeps the path's Poiseuille pressure drop within\n"
         "    0.5 % of the density, an end time five settling times (resistance x compliance) past the ramp. The\n"
         "    waveform file: lines time_s,factor over one cycle",
         simulateSph},
        {"simulate injection", 1, 1,
         {kStudy, value("needle-bore"), value("rate"), value("needle-end"), value("box-depth"), value("box-margin"),
          value("spacing"), value("until"), value("void-fraction"), value("gauge"), value("frames"), value("backend"),
          value("centerlines"), kParam, value("out"), kWait},
         "simulate injection --study <study.vsim> [--needle-bore 1.2mm] [--rate 300/s] [--needle-end NODE]\n"
         "                   [--box-depth 15mm] [--box-margin 10mm] [--spacing 0.4mm] [--until 0.3s]\n"
         "                   [--void-fraction 0.2] [--gauge 40mmHg] [--frames 10] [--backend auto|cpu|cuda]\n"
         "                   [--param key=value ...] [--out DIR]\n"
         "    thesis scenario (a), the needle injection (ch. 5.5.1, Table 5.1): the vessel held upright (gravity from\n"
         "    the needle's end, the largest vessel's or NODE, towards the others), empty at the start; a needle of\n"
         "    the bore at that end emits --rate particles of the spacing a second (default a third of the bore) of\n"
         "    the mixture at --void-fraction; the blood runs down and out of the open ends into a box below them;\n"
         "    --gauge is the level every pressure is reported at. Prints the fill over the frames (ml in the vessel\n"
         "    and in the box, how far the blood has run) and the mass balance; a Run of particle frames; the frame\n"
         "    series to DIR. Wall absorption of the injected drug: --param absorption_distance_mm=0.1 (CPU)",
         simulateInjection},
        {"simulate smoke", 1, 1,
         {kStudy, value("scenario"), value("grid"), value("particles"), value("frames"), value("backend"), kParam,
          value("out"), kWait},
         "simulate smoke --study <study.vsim> [--scenario ball-drop|evh|liver-ablation] [--grid 64] [--particles N]\n"
         "               [--frames 20] [--backend auto|cpu|cuda] [--param key=value ...] [--out DIR]\n"
         "    surgical smoke (thesis ch. 7, illustrative scenes): ball-drop (the thesis demo, a 1 m box), evh (a CO2\n"
         "    tunnel around the study's longest centerline segment, smoke from 9 s after the cautery's contact),\n"
         "    liver-ablation (a dome over the study's liver label, else a box phantom, with a suction port); stable\n"
         "    fluids with vorticity confinement and vortex particles, the projection by MGPCG. Prints the\n"
         "    endoscope's obscuration curve (Beer-Lambert, K_m 8.7 m^2/g) with the times to 50 % and 90 %, a Run of\n"
         "    smoke density frames; the frame series to DIR. `vascusim-cli parameters smoke` lists the parameters",
         simulateSmoke},
        {"pacs echo", 1, 1, pacsNodeAnd({}),
         "pacs echo --aet AE --host HOST --port N [--calling-aet VASCUSIM] [--timeout 30]\n"
         "          [--tls --tls-trusted PACS.pem [--tls-cert OURS.pem --tls-key OURS.key]]\n"
         "    C-ECHO to a PACS node: exit 0 when it answers, else 1 with the reason (connection refused or silent,\n"
         "    association rejected: our AE title not registered there, or its AE title not AE). --tls: DICOM TLS\n"
         "    (BCP 195), the PACS's certificate verified against --tls-trusted; ours shown when given (PEM files,\n"
         "    the key not encrypted). Every pacs command takes these node options",
         pacsEchoCommand},
        {"pacs find", 1, 1, pacsNodeAnd({value("level"), value("patient-name"), value("patient-id"), value("date"),
                                         value("modality"), value("study-uid")}),
         "pacs find --aet AE --host HOST --port N [--level patient|study|series] [--patient-name 'DOE^J*']\n"
         "          [--patient-id ID] [--date YYYYMMDD[-YYYYMMDD]] [--modality CT] [--study-uid UID]\n"
         "    C-FIND as JSON, names in UTF-8. study (default; Study Root): UID, patient, date, description,\n"
         "    accession number, modalities, number of series; patient (Patient Root; --patient-name, --patient-id):\n"
         "    name, ID, birth date, sex, number of studies; series (--study-uid required; --modality): UID,\n"
         "    modality, number, description, date, number of instances",
         pacsFindCommand},
        {"pacs get", 1, 1, pacsNodeAnd({required("study-uid"), value("series-uid"), required("out"), value("move")}),
         "pacs get --aet AE --host HOST --port N --study-uid UID [--series-uid UID] --out DIR [--move PORT]\n"
         "    C-GET of a study, or of one series of it (CT, enhanced CT, SEG, encapsulated PDF, secondary capture)\n"
         "    into DIR/dicom (DIR new, empty or VascuSim's); a failed, partial or cancelled transfer leaves no\n"
         "    files. --move PORT: by C-MOVE instead, to our own listener on PORT (the PACS must know our AE title\n"
         "    there; on a TLS node the listener needs --tls-cert and --tls-key). Then: import DIR/dicom --study S\n"
         "    (a series already in S is recognised and not imported twice)",
         pacsGetCommand},
        {"pacs store", 2, 100000, pacsNodeAnd({value("anonymized"), kUidRoot}),
         "pacs store FILE.dcm... --aet AE --host HOST --port N [--anonymized refuse|new-study] [--uid-root ROOT]\n"
         "    C-STORE of DICOM files (the report's --dicom-pdf, export-label's SEG) into the study each names.\n"
         "    Every file is checked first: a de-identified one (report --anonymize) is refused, nothing sent, unless\n"
         "    --anonymized new-study, which stores it as a new study under new UIDs (the file is not changed)",
         pacsStoreCommand},
        {"validate", 1, 1, {value("backend"), value("particles"), value("until")},
         "validate <case|fem|network|sph|heat|all> [--backend auto|cpu|cuda] [--particles N] [--until T]\n"
         "    analytic validation (JSON) of the wall solver (fem-patch, fem-rotation, fem-cantilever, fem-lame,\n"
         "    fem-lame-quadratic, fem-damping), the drug network (network-cylinder, network-cone,\n"
         "    network-conservation, network-bifurcation, network-confluence), the blood flow (sph-kernel, sph-fpm,\n"
         "    sph-hydrostatic, sph-poiseuille, sph-womersley, sph-mass, sph-stenosis: minutes each on 2 cores;\n"
         "    sph-dambreak: SPHERIC benchmark 2 against the experiment's probes, about 2 minutes on a GPU at its\n"
         "    1,000,000 particles, left out of 'all' and 'sph' without one; --backend, --particles and --until (s,\n"
         "    within the record's 1.02 s; a shorter run never passes) set it) and the run driver's template solver\n"
         "    (heat-decay); exit 0 only when every figure is within its tolerance",
         validateSolvers},
        {"report", 0, 0,
         {kStudy, required("out"), value("sections"), value("page"), value("dicom-pdf"), flag("anonymize"),
          value("metrics-csv"), value("metrics-json"), flag("no-validation"), flag("overwrite"), value("language"), kWait,
          kUidRoot},
         "report --study <study.vsim> --out <report.pdf> [--sections aaa,stenosis,chemoembolization,smoke,measurements,runs]\n"
         "       [--page a4|letter] [--dicom-pdf <out.dcm>] [--anonymize] [--metrics-csv F] [--metrics-json F]\n"
         "       [--no-validation] [--overwrite] [--language en|de|zh_CN|<catalogue.qm>] [--uid-root ROOT]\n"
         "    the clinical report (PDF) in English (default), German or Simplified Chinese (or a compiled\n"
         "    translation); existing output files are replaced only with --overwrite. --anonymize: no patient\n"
         "    identifiers, and the DICOM PDF is its own new study (Patient Identity Removed YES). --uid-root: the\n"
         "    organisation's DICOM UID root (default: 2.25 UUID UIDs)",
         writeReport},
        {"demo", 0, 0, {required("out"), value("size")},
         "demo --out <dir> [--size 512x512x400]\n"
         "    the aaa, hepatic-tree and stenosis phantoms through the whole pipeline, each study with its report,\n"
         "    into a new or empty folder",
         runDemo},
        {"demo-study", 0, 0, {value("out")},
         "demo-study [--out <study.vsim>]\n"
         "    write the built-in demo study (default: ~/.local/share/VascuSim/demo.vsim) unless it exists",
         writeDemoStudy},
    };
}

} // namespace

const std::vector<CommandSpec>& commandSpecs()
{
    static const std::vector<CommandSpec> specs = declareCommands();
    return specs;
}

} // namespace vsim::cli
