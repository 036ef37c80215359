<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>QObject</name>
    <message>
        <source>Writing the demo study (aaa phantom)...</source>
        <translation>Demo-Studie wird geschrieben (AAA-Phantom)...</translation>
    </message>
    <message>
        <source>Rename &quot;%1&quot;</source>
        <translation>&quot;%1&quot; umbenennen</translation>
    </message>
    <message>
        <source>Delete &quot;%1&quot;</source>
        <translation>&quot;%1&quot; löschen</translation>
    </message>
    <message>
        <source>cannot be placed</source>
        <translation>nicht platzierbar</translation>
    </message>
    <message>
        <source>Paint label</source>
        <translation>Label malen</translation>
    </message>
    <message>
        <source>Erase label</source>
        <translation>Label radieren</translation>
    </message>
    <message>
        <source>Name segment %1 &quot;%2&quot;</source>
        <translation>Segment %1 „%2“ benennen</translation>
    </message>
    <message>
        <source>Remove island</source>
        <translation>Insel entfernen</translation>
    </message>
</context>
<context>
    <name>Report</name>
    <message>
        <source>(not recorded)</source>
        <translation>(nicht erfasst)</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patient</translation>
    </message>
    <message>
        <source>anonymized</source>
        <translation>anonymisiert</translation>
    </message>
    <message>
        <source>Patient ID</source>
        <translation>Patienten-ID</translation>
    </message>
    <message>
        <source>Birth date</source>
        <translation>Geburtsdatum</translation>
    </message>
    <message>
        <source>Institution</source>
        <translation>Einrichtung</translation>
    </message>
    <message>
        <source>Study date</source>
        <translation>Untersuchungsdatum</translation>
    </message>
    <message>
        <source>Study</source>
        <translation>Untersuchung</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>Serie</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>Software</translation>
    </message>
    <message>
        <source>Report date</source>
        <translation>Berichtsdatum</translation>
    </message>
    <message>
        <source>Analyses not run</source>
        <translation>Nicht durchgeführte Analysen</translation>
    </message>
    <message>
        <source>planning support, needs clinical judgement</source>
        <translation>Planungsunterstützung, erfordert klinische Beurteilung</translation>
    </message>
    <message>
        <source>page %1</source>
        <translation>Seite %1</translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>Kenngröße</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Results are computed from the patient&apos;s images by physical models for planning support only. They are not a diagnosis and need clinical judgement.</source>
        <translation>Die Ergebnisse werden mit physikalischen Modellen aus den Bildern des Patienten berechnet und dienen nur der Planungsunterstützung. Sie sind keine Diagnose und erfordern eine klinische Beurteilung.</translation>
    </message>
    <message>
        <source>Measurements marked for the report on the workstation. Points in the patient frame (LPS, mm).</source>
        <translation>Auf der Workstation für den Bericht markierte Messungen. Punkte im Patientenkoordinatensystem (LPS, mm).</translation>
    </message>
    <message>
        <source>Measurement</source>
        <translation>Messung</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>Messwert</translation>
    </message>
    <message>
        <source>Definition</source>
        <translation>Definition</translation>
    </message>
    <message>
        <source>Points [mm]</source>
        <translation>Punkte [mm]</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <source>Filling of the tree downstream of the tip</source>
        <translation>Füllung des Gefäßbaums distal der Katheterspitze</translation>
    </message>
    <message>
        <source>Time from the start of the injection [s]</source>
        <translation>Zeit ab Injektionsbeginn [s]</translation>
    </message>
    <message>
        <source>Volume filled by the drug [%]</source>
        <translation>Vom Wirkstoff gefülltes Volumen [%]</translation>
    </message>
    <message>
        <source>filled</source>
        <translation>gefüllt</translation>
    </message>
    <message>
        <source>Drug flow per branch (segments downstream of the tip, largest flow first)</source>
        <translation>Wirkstofffluss je Ast (Segmente distal der Spitze, größter Fluss zuerst)</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>Nodes</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Radius [mm]</source>
        <translation>Radius [mm]</translation>
    </message>
    <message>
        <source>Length [mm]</source>
        <translation>Länge [mm]</translation>
    </message>
    <message>
        <source>Drug flow [ml/min]</source>
        <translation>Wirkstofffluss [ml/min]</translation>
    </message>
    <message>
        <source>Share [%]</source>
        <translation>Anteil [%]</translation>
    </message>
    <message>
        <source>Filled after [s]</source>
        <translation>Gefüllt nach [s]</translation>
    </message>
    <message>
        <source>never</source>
        <translation>nie</translation>
    </message>
    <message>
        <source>%1 more</source>
        <translation>%1 weitere</translation>
    </message>
    <message>
        <source>Chemoembolization: drug delivery through the hepatic arteries</source>
        <translation>Chemoembolisation: Wirkstoffgabe über die Leberarterien</translation>
    </message>
    <message>
        <source>sphere x,y,z,radius %1 mm</source>
        <translation>Kugel x,y,z,Radius %1 mm</translation>
    </message>
    <message>
        <source>label %1</source>
        <translation>Label %1</translation>
    </message>
    <message>
        <source>none given</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <source>Catheter tip: %1 (a node of the network, or a point x,y,z in mm, patient LPS). Tumour: %2. Blood enters at: %3.</source>
        <translation>Katheterspitze: %1 (ein Knoten des Netzes oder ein Punkt x,y,z in mm, Patienten-LPS). Tumor: %2. Bluteinstrom: %3.</translation>
    </message>
    <message>
        <source>the root of the tree</source>
        <translation>die Wurzel des Gefäßbaums</translation>
    </message>
    <message>
        <source>the tree&apos;s largest end</source>
        <translation>das größte Ende des Gefäßbaums</translation>
    </message>
    <message>
        <source>Feeders added by hand: segments %1.</source>
        <translation>Von Hand hinzugefügte Feeder: Segmente %1.</translation>
    </message>
    <message>
        <source>Feeders removed by hand: segments %1.</source>
        <translation>Von Hand entfernte Feeder: Segmente %1.</translation>
    </message>
    <message>
        <source>Injection and filling</source>
        <translation>Injektion und Füllung</translation>
    </message>
    <message>
        <source>Injected mixture</source>
        <translation>Injiziertes Gemisch</translation>
    </message>
    <message>
        <source>Injected mass</source>
        <translation>Injizierte Masse</translation>
    </message>
    <message>
        <source>Gas void fraction</source>
        <translation>Gasvolumenanteil</translation>
    </message>
    <message>
        <source>Mixture density</source>
        <translation>Dichte des Gemischs</translation>
    </message>
    <message>
        <source>Mixture viscosity</source>
        <translation>Viskosität des Gemischs</translation>
    </message>
    <message>
        <source>Pressure at the tip</source>
        <translation>Druck an der Spitze</translation>
    </message>
    <message>
        <source>First outlet reached after</source>
        <translation>Erster Ausgang erreicht nach</translation>
    </message>
    <message>
        <source>Last outlet reached after</source>
        <translation>Letzter Ausgang erreicht nach</translation>
    </message>
    <message>
        <source>Outlets downstream of the tip</source>
        <translation>Ausgänge distal der Spitze</translation>
    </message>
    <message>
        <source>Largest Reynolds number</source>
        <translation>Größte Reynolds-Zahl</translation>
    </message>
    <message>
        <source>Blood flow and the catheter (time-averaged, Newtonian blood)</source>
        <translation>Blutfluss und Katheter (zeitgemittelt, newtonsches Blut)</translation>
    </message>
    <message>
        <source>Arterial inflow at the tree&apos;s root</source>
        <translation>Arterieller Zufluss an der Wurzel des Gefäßbaums</translation>
    </message>
    <message>
        <source>Mean pressure at the root</source>
        <translation>Mittlerer Druck an der Wurzel</translation>
    </message>
    <message>
        <source>Vessel&apos;s own flow at the tip (catheter in, no injection)</source>
        <translation>Eigenfluss des Gefäßes an der Spitze (Katheter liegt, keine Injektion)</translation>
    </message>
    <message>
        <source>Blood reaching the tip during the injection</source>
        <translation>Blut, das während der Injektion die Spitze erreicht</translation>
    </message>
    <message>
        <source>Injected mixture in the flow below the tip (volume)</source>
        <translation>Injiziertes Gemisch im Fluss distal der Spitze (Volumen)</translation>
    </message>
    <message>
        <source>Drug (liquid phase) in the flow below the tip (volume)</source>
        <translation>Wirkstoff (flüssige Phase) im Fluss distal der Spitze (Volumen)</translation>
    </message>
    <message>
        <source>Catheter&apos;s share of the lumen at the tip (area)</source>
        <translation>Anteil des Katheters am Lumen an der Spitze (Fläche)</translation>
    </message>
    <message>
        <source>Wedged catheter (1: yes)</source>
        <translation>Katheter in Wedge-Position (1: ja)</translation>
    </message>
    <message>
        <source>Drug refluxing past the tip</source>
        <translation>Wirkstoffreflux an der Spitze vorbei</translation>
    </message>
    <message>
        <source>Fixed-point iterations (fractions and viscosities)</source>
        <translation>Fixpunktiterationen (Anteile und Viskositäten)</translation>
    </message>
    <message>
        <source>Perfusion territory and tumour coverage (TACE grading: A lesion and margin, B lesion only, C lesion partly; margin 5 mm under 25 mm, else 10 mm)</source>
        <translation>Perfusionsterritorium und Tumorabdeckung (TACE-Einteilung: A Läsion und Saum, B nur Läsion, C Läsion teilweise; Saum 5 mm unter 25 mm, sonst 10 mm)</translation>
    </message>
    <message>
        <source>Liver (label)</source>
        <translation>Leber (Label)</translation>
    </message>
    <message>
        <source>Perfused territory from the tip</source>
        <translation>Von der Spitze aus perfundiertes Territorium</translation>
    </message>
    <message>
        <source>Tumour in the territory</source>
        <translation>Tumor im Territorium</translation>
    </message>
    <message>
        <source>Non-tumour liver in the territory</source>
        <translation>Nicht-tumoröse Leber im Territorium</translation>
    </message>
    <message>
        <source>Coverage grade (1 A, 2 B, 3 C)</source>
        <translation>Abdeckungsgrad (1 A, 2 B, 3 C)</translation>
    </message>
    <message>
        <source>Lesion 1: longest diameter</source>
        <translation>Läsion 1: größter Durchmesser</translation>
    </message>
    <message>
        <source>Lesion 1: margin</source>
        <translation>Läsion 1: Saum</translation>
    </message>
    <message>
        <source>Lesion 1: covered</source>
        <translation>Läsion 1: abgedeckt</translation>
    </message>
    <message>
        <source>Lesion 1: margin covered</source>
        <translation>Läsion 1: Saum abgedeckt</translation>
    </message>
    <message>
        <source>Feeders (found: entering lesion + margin, or feeding 1 % of it; with the user&apos;s edits)</source>
        <translation>Feeder (gefunden: in Läsion + Saum eintretend oder 1 % davon versorgend; mit den Änderungen des Benutzers)</translation>
    </message>
    <message>
        <source>Feeders added by hand</source>
        <translation>Von Hand hinzugefügte Feeder</translation>
    </message>
    <message>
        <source>Feeders found and removed by hand</source>
        <translation>Gefundene und von Hand entfernte Feeder</translation>
    </message>
    <message>
        <source>Feeders the drug from the tip reaches</source>
        <translation>Feeder, die der Wirkstoff von der Spitze aus erreicht</translation>
    </message>
    <message>
        <source>Drug to non-tumour liver</source>
        <translation>Wirkstoff in nicht-tumoröse Leber</translation>
    </message>
    <message>
        <source>Drug leaving the liver (extrahepatic outlets)</source>
        <translation>Wirkstoff, der die Leber verlässt (extrahepatische Ausgänge)</translation>
    </message>
    <message>
        <source>Best tip position&apos;s grade (1 A, 2 B, 3 C)</source>
        <translation>Grad der besten Spitzenposition (1 A, 2 B, 3 C)</translation>
    </message>
    <message>
        <source>Best tip position&apos;s non-tumour liver</source>
        <translation>Nicht-tumoröse Leber bei der besten Spitzenposition</translation>
    </message>
    <message>
        <source>Working C-arm angle for the path to the tip (patient supine; + LAO / - RAO, + cranial / - caudal; within LAO/RAO 60 and cranial/caudal 40 degrees)</source>
        <translation>Arbeitswinkel des C-Bogens für den Weg zur Spitze (Patient in Rückenlage; + LAO / - RAO, + kranial / - kaudal; innerhalb LAO/RAO 60 und kranial/kaudal 40 Grad)</translation>
    </message>
    <message>
        <source>Path from node (the common hepatic artery&apos;s upper end when named, else the root)</source>
        <translation>Weg ab Knoten (oberes Ende der A. hepatica communis, wenn benannt, sonst die Wurzel)</translation>
    </message>
    <message>
        <source>LAO (+) / RAO (-)</source>
        <translation>LAO (+) / RAO (-)</translation>
    </message>
    <message>
        <source>Cranial (+) / caudal (-)</source>
        <translation>Kranial (+) / kaudal (-)</translation>
    </message>
    <message>
        <source>Path foreshortened at the working angle</source>
        <translation>Verkürzung des Wegs im Arbeitswinkel</translation>
    </message>
    <message>
        <source>Path overlapped by other vessels at the working angle</source>
        <translation>Überlagerung des Wegs durch andere Gefäße im Arbeitswinkel</translation>
    </message>
    <message>
        <source>Path foreshortened from the front (AP)</source>
        <translation>Verkürzung des Wegs von vorn (AP)</translation>
    </message>
    <message>
        <source>Path overlapped from the front (AP)</source>
        <translation>Überlagerung des Wegs von vorn (AP)</translation>
    </message>
    <message>
        <source>Targeting</source>
        <translation>Zielgenauigkeit</translation>
    </message>
    <message>
        <source>Drug reaching the tumour</source>
        <translation>Wirkstoff, der den Tumor erreicht</translation>
    </message>
    <message>
        <source>Drug reaching non-target liver</source>
        <translation>Wirkstoff, der Nicht-Ziel-Leber erreicht</translation>
    </message>
    <message>
        <source>Outlets feeding the tumour</source>
        <translation>Ausgänge, die den Tumor versorgen</translation>
    </message>
    <message>
        <source>Tumour share at the best tip position</source>
        <translation>Tumoranteil bei der besten Spitzenposition</translation>
    </message>
    <message>
        <source>Candidate catheter tip positions, ranked by coverage grade, then the lesions&apos; share perfused, then the least non-tumour liver perfused</source>
        <translation>Mögliche Positionen der Katheterspitze, geordnet nach Abdeckungsgrad, dann nach perfundiertem Anteil der Läsionen, dann nach der geringsten perfundierten nicht-tumorösen Leber</translation>
    </message>
    <message>
        <source>Candidate catheter tip positions, ranked by the drug share reaching the tumour</source>
        <translation>Mögliche Positionen der Katheterspitze, geordnet nach dem Wirkstoffanteil, der den Tumor erreicht</translation>
    </message>
    <message>
        <source>Rank</source>
        <translation>Rang</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>Position x, y, z [mm]</source>
        <translation>Position x, y, z [mm]</translation>
    </message>
    <message>
        <source>Tumour share [%]</source>
        <translation>Tumoranteil [%]</translation>
    </message>
    <message>
        <source>Depth [segments]</source>
        <translation>Tiefe [Segmente]</translation>
    </message>
    <message>
        <source>Grade</source>
        <translation>Grad</translation>
    </message>
    <message>
        <source>Lesions perfused [%]</source>
        <translation>Perfundierte Läsionen [%]</translation>
    </message>
    <message>
        <source>Non-tumour liver [ml]</source>
        <translation>Nicht-tumoröse Leber [ml]</translation>
    </message>
    <message>
        <source>Two-phase drug against a pure liquid at the control points</source>
        <translation>Zweiphasiger Wirkstoff gegenüber reiner Flüssigkeit an den Kontrollpunkten</translation>
    </message>
    <message>
        <source>A: drug flow, two-phase</source>
        <translation>A: Wirkstofffluss, zweiphasig</translation>
    </message>
    <message>
        <source>A: drug flow, pure liquid</source>
        <translation>A: Wirkstofffluss, reine Flüssigkeit</translation>
    </message>
    <message>
        <source>A: two-phase lower by (same injected rate)</source>
        <translation>A: zweiphasig niedriger um (gleiche Injektionsrate)</translation>
    </message>
    <message>
        <source>A: two-phase lower by (same tip pressure)</source>
        <translation>A: zweiphasig niedriger um (gleicher Druck an der Spitze)</translation>
    </message>
    <message>
        <source>A: whole flow, two-phase against liquid (split shift)</source>
        <translation>A: Gesamtfluss, zweiphasig gegenüber Flüssigkeit (Verschiebung der Aufteilung)</translation>
    </message>
    <message>
        <source>B: drug flow, two-phase</source>
        <translation>B: Wirkstofffluss, zweiphasig</translation>
    </message>
    <message>
        <source>B: drug flow, pure liquid</source>
        <translation>B: Wirkstofffluss, reine Flüssigkeit</translation>
    </message>
    <message>
        <source>B: two-phase lower by (same injected rate)</source>
        <translation>B: zweiphasig niedriger um (gleiche Injektionsrate)</translation>
    </message>
    <message>
        <source>B: two-phase lower by (same tip pressure)</source>
        <translation>B: zweiphasig niedriger um (gleicher Druck an der Spitze)</translation>
    </message>
    <message>
        <source>B: whole flow, two-phase against liquid (split shift)</source>
        <translation>B: Gesamtfluss, zweiphasig gegenüber Flüssigkeit (Verschiebung der Aufteilung)</translation>
    </message>
    <message>
        <source>The drug flow is the liquid phase&apos;s volume flow, (1 - v) c Q, with v the void fraction and c the injected mixture&apos;s share of the flow (1 when the drug flows alone); the pure liquid is the same injection with v = 0 (thesis ch. 6.4). Its drop is close to v by that definition. The split shift is the change of the whole flow: what the mixture&apos;s other viscosity does to the split.</source>
        <translation>Der Wirkstofffluss ist der Volumenstrom der flüssigen Phase, (1 - v) c Q, mit v dem Gasvolumenanteil und c dem Anteil des injizierten Gemischs am Fluss (1, wenn der Wirkstoff allein fließt); die reine Flüssigkeit ist dieselbe Injektion mit v = 0 (Dissertation Kap. 6.4). Ihr Rückgang liegt nach dieser Definition nahe bei v. Die Verschiebung der Aufteilung ist die Änderung des Gesamtflusses: was die andere Viskosität des Gemischs an der Aufteilung ändert.</translation>
    </message>
    <message>
        <source>The tree coloured by drug flow (ml/min; grey: no drug), seen from the front</source>
        <translation>Der Gefäßbaum nach Wirkstofffluss eingefärbt (ml/min; grau: kein Wirkstoff), Ansicht von vorn</translation>
    </message>
    <message>
        <source>drug flow [ml/min]</source>
        <translation>Wirkstofffluss [ml/min]</translation>
    </message>
    <message>
        <source>Wall mechanics: tetrahedral FEM (co-rotational linear elasticity or St. Venant-Kirchhoff), lumped mass, Rayleigh damping, backward Euler with block-Jacobi preconditioned CG (thesis ch. 4); the physiological protocol&apos;s figures from the static equilibrium after the load path.</source>
        <translation>Wandmechanik: Tetraeder-FEM (korotierende lineare Elastizität oder St. Venant-Kirchhoff), konzentrierte Masse, Rayleigh-Dämpfung, implizites Euler-Verfahren mit Block-Jacobi-vorkonditioniertem CG (Dissertation Kap. 4); die Werte des physiologischen Protokolls aus dem statischen Gleichgewicht nach dem Lastpfad.</translation>
    </message>
    <message>
        <source>Blood flow: weakly compressible SPH (thesis ch. 5; Liu quartic kernel, Tait equation of state, delta-SPH density diffusion, Morris viscosity with no-slip walls whose pressure is extrapolated from the blood, leapfrog with an adaptive step) on particles seeded in the lumen label; a flow-rate inlet at the largest vessel&apos;s end and pressure outlets with particle buffers; double precision on the CPU.</source>
        <translation>Blutfluss: schwach kompressibles SPH (Dissertation Kap. 5; quartischer Liu-Kern, Tait-Zustandsgleichung, Delta-SPH-Dichtediffusion, Morris-Viskosität mit haftenden Wänden, deren Druck aus dem Blut extrapoliert wird, Leapfrog mit adaptivem Zeitschritt) auf Partikeln, die im Lumen-Label gesetzt werden; ein Volumenstrom-Einlass am Ende des größten Gefäßes und Druckauslässe mit Partikelpuffern; doppelte Genauigkeit auf der CPU.</translation>
    </message>
    <message>
        <source>the CPU backend in double precision, explicit steps (no linear solves)</source>
        <translation>auf dem CPU-Backend in doppelter Genauigkeit, explizite Schritte (keine linearen Löser)</translation>
    </message>
    <message>
        <source>Drug delivery: two-phase homogeneous fluid in a network of conical Hagen-Poiseuille pipes, Kirchhoff solve, plug filling (thesis ch. 6).</source>
        <translation>Wirkstoffgabe: zweiphasiges homogenes Fluid in einem Netz konischer Hagen-Poiseuille-Rohre, Kirchhoff-Lösung, Pfropfenfüllung (Dissertation Kap. 6).</translation>
    </message>
    <message>
        <source>the run used the %1 backend, the cases the %2</source>
        <translation>der Lauf nutzte das Backend %1, die Fälle %2</translation>
    </message>
    <message>
        <source>the run&apos;s linear solves were direct (factorised), the cases&apos; iterative (at most %1 iterations)</source>
        <translation>die linearen Lösungen des Laufs waren direkt (faktorisiert), die der Fälle iterativ (höchstens %1 Iterationen)</translation>
    </message>
    <message>
        <source>the run&apos;s solves stopped at %1 iterations, the cases&apos; at %2</source>
        <translation>die Lösungen des Laufs endeten bei %1 Iterationen, die der Fälle bei %2</translation>
    </message>
    <message>
        <source>the run solved to a relative residual of %1, the cases to %2 or tighter</source>
        <translation>der Lauf löste bis zu einem relativen Residuum von %1, die Fälle bis %2 oder enger</translation>
    </message>
    <message>
        <source>The cases ran %1.</source>
        <translation>Die Fälle liefen %1.</translation>
    </message>
    <message>
        <source>That is the configuration of the reported run.</source>
        <translation>Das ist die Konfiguration des berichteten Laufs.</translation>
    </message>
    <message>
        <source>What differs from the reported run: %1. The cases show the method, not this run&apos;s solver settings.</source>
        <translation>Abweichungen vom berichteten Lauf: %1. Die Fälle belegen die Methode, nicht die Lösereinstellungen dieses Laufs.</translation>
    </message>
    <message>
        <source>Runs: parameters, solver, validation</source>
        <translation>Läufe: Parameter, Löser, Validierung</translation>
    </message>
    <message>
        <source>Item</source>
        <translation>Eintrag</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Befehl</translation>
    </message>
    <message>
        <source>Backend</source>
        <translation>Backend</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>1 (steady solve)</source>
        <translation>1 (stationäre Lösung)</translation>
    </message>
    <message>
        <source>Wall-clock time</source>
        <translation>Laufzeit</translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation>nicht erfasst</translation>
    </message>
    <message>
        <source>Convergence</source>
        <translation>Konvergenz</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Eingaben</translation>
    </message>
    <message>
        <source>Made</source>
        <translation>Erstellt</translation>
    </message>
    <message>
        <source>%1 by VascuSim %2</source>
        <translation>%1 mit VascuSim %2</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Parameters of %1</source>
        <translation>Parameter von %1</translation>
    </message>
    <message>
        <source>Validation of this solver in this build (vascusim-cli validate)</source>
        <translation>Validierung dieses Lösers in diesem Build (vascusim-cli validate)</translation>
    </message>
    <message>
        <source>Case</source>
        <translation>Fall</translation>
    </message>
    <message>
        <source>What is compared</source>
        <translation>Was verglichen wird</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>bestanden</translation>
    </message>
    <message>
        <source>FAILED</source>
        <translation>NICHT BESTANDEN</translation>
    </message>
    <message>
        <source>Distance along the centerline from the inlet [mm]</source>
        <translation>Abstand entlang der Mittellinie vom Einlass [mm]</translation>
    </message>
    <message>
        <source>Velocity along the centerline (cross-sections of the same run, time-averaged)</source>
        <translation>Geschwindigkeit entlang der Mittellinie (Querschnitte desselben Laufs, zeitgemittelt)</translation>
    </message>
    <message>
        <source>Velocity [m/s]</source>
        <translation>Geschwindigkeit [m/s]</translation>
    </message>
    <message>
        <source>peak (fastest 5 % of the section)</source>
        <translation>Spitze (schnellste 5 % des Querschnitts)</translation>
    </message>
    <message>
        <source>mean (flow rate / area)</source>
        <translation>Mittel (Volumenstrom / Fläche)</translation>
    </message>
    <message>
        <source>Mean pressure along the centerline (gauge; the same sections)</source>
        <translation>Mittlerer Druck entlang der Mittellinie (Überdruck; dieselben Querschnitte)</translation>
    </message>
    <message>
        <source>Pressure [mmHg]</source>
        <translation>Druck [mmHg]</translation>
    </message>
    <message>
        <source>section mean</source>
        <translation>Querschnittsmittel</translation>
    </message>
    <message>
        <source>largest TAWSS %1 Pa</source>
        <translation>größte TAWSS %1 Pa</translation>
    </message>
    <message>
        <source>TAWSS [Pa]</source>
        <translation>TAWSS [Pa]</translation>
    </message>
    <message>
        <source>Stenosis / blockage</source>
        <translation>Stenose / Verschluss</translation>
    </message>
    <message>
        <source>The narrowest segment (cross-sections perpendicular to the centerline)</source>
        <translation>Das engste Segment (Querschnitte senkrecht zur Mittellinie)</translation>
    </message>
    <message>
        <source>Diameter stenosis</source>
        <translation>Durchmesserstenose</translation>
    </message>
    <message>
        <source>Area stenosis</source>
        <translation>Flächenstenose</translation>
    </message>
    <message>
        <source>Reference diameter (median)</source>
        <translation>Referenzdurchmesser (Median)</translation>
    </message>
    <message>
        <source>Minimal diameter</source>
        <translation>Minimaler Durchmesser</translation>
    </message>
    <message>
        <source>Segment length</source>
        <translation>Segmentlänge</translation>
    </message>
    <message>
        <source>Diameter along the narrowest segment</source>
        <translation>Durchmesser entlang des engsten Segments</translation>
    </message>
    <message>
        <source>reference diameter</source>
        <translation>Referenzdurchmesser</translation>
    </message>
    <message>
        <source>Blockage velocity ratios and the pressure drop come from a blood-flow run (Flow &gt; Blood Flow, vascusim-cli simulate sph); the study&apos;s run has no settled flow to measure them (see its warnings).</source>
        <translation>Geschwindigkeitsverhältnisse und Druckabfall an der Engstelle stammen aus einem Blutflusslauf (Fluss &gt; Blutfluss, vascusim-cli simulate sph); der Lauf dieser Studie hat keinen eingeschwungenen Fluss, an dem sie sich messen ließen (siehe seine Warnungen).</translation>
    </message>
    <message>
        <source>Blockage velocity ratios and the pressure drop come from a blood-flow run (Flow &gt; Blood Flow, vascusim-cli simulate sph); this study has none.</source>
        <translation>Geschwindigkeitsverhältnisse und Druckabfall an der Engstelle stammen aus einem Blutflusslauf (Fluss &gt; Blutfluss, vascusim-cli simulate sph); diese Studie hat keinen.</translation>
    </message>
    <message>
        <source>Blood flow (SPH run %1): the throat against the sections %2 mm upstream and downstream along the centerline, time-averaged over the settled flow; pressures gauge, the outlets at %3 mmHg</source>
        <translation>Blutfluss (SPH-Lauf %1): die Engstelle gegenüber den Querschnitten %2 mm stromauf und stromab entlang der Mittellinie, zeitgemittelt über den eingeschwungenen Fluss; Drücke als Überdruck, die Auslässe bei %3 mmHg</translation>
    </message>
    <message>
        <source>Peak velocity ratio, throat / upstream (PSV ratio&apos;s counterpart)</source>
        <translation>Verhältnis der Spitzengeschwindigkeit, Engstelle / stromauf (Gegenstück zum PSV-Verhältnis)</translation>
    </message>
    <message>
        <source>Peak velocity ratio, throat / downstream</source>
        <translation>Verhältnis der Spitzengeschwindigkeit, Engstelle / stromab</translation>
    </message>
    <message>
        <source>Mean velocity ratio, throat / upstream (a mass check)</source>
        <translation>Verhältnis der mittleren Geschwindigkeit, Engstelle / stromauf (eine Massenprüfung)</translation>
    </message>
    <message>
        <source>Flow area ratio, upstream / throat (from the particles)</source>
        <translation>Verhältnis der Strömungsfläche, stromauf / Engstelle (aus den Partikeln)</translation>
    </message>
    <message>
        <source>Throat peak velocity (fastest 5 % of the section)</source>
        <translation>Spitzengeschwindigkeit in der Engstelle (schnellste 5 % des Querschnitts)</translation>
    </message>
    <message>
        <source>Pressure drop, upstream - downstream (section means)</source>
        <translation>Druckabfall, stromauf - stromab (Querschnittsmittel)</translation>
    </message>
    <message>
        <source>Distal / proximal pressure (gauge)</source>
        <translation>Distaler / proximaler Druck (Überdruck)</translation>
    </message>
    <message>
        <source>Flow rate throat / upstream (1 when settled)</source>
        <translation>Volumenstrom Engstelle / stromauf (1 im eingeschwungenen Zustand)</translation>
    </message>
    <message>
        <source>Largest time-averaged wall shear stress (TAWSS)</source>
        <translation>Größte zeitgemittelte Wandschubspannung (TAWSS)</translation>
    </message>
    <message>
        <source>Mean TAWSS over the surface</source>
        <translation>Mittlere TAWSS über die Oberfläche</translation>
    </message>
    <message>
        <source>Largest oscillatory shear index (0: steady)</source>
        <translation>Größter oszillatorischer Scherindex (0: stationär)</translation>
    </message>
    <message>
        <source>Highest wall pressure (gauge)</source>
        <translation>Höchster Wanddruck (Überdruck)</translation>
    </message>
    <message>
        <source>Lowest wall pressure (gauge)</source>
        <translation>Niedrigster Wanddruck (Überdruck)</translation>
    </message>
    <message>
        <source>Time-averaged wall shear stress (TAWSS, Pa) on the lumen surface, averaged over %1-%2 ms of the same run, seen from the front; grey: no value (past an open end, or within a kernel support of it)</source>
        <translation>Zeitgemittelte Wandschubspannung (TAWSS, Pa) auf der Lumenoberfläche, gemittelt über %1-%2 ms desselben Laufs, Ansicht von vorn; grau: kein Wert (jenseits eines offenen Endes oder innerhalb eines Kernträgers davon)</translation>
    </message>
    <message>
        <source>These blood-flow figures come from a run that is %1.</source>
        <translation>Diese Blutflusswerte stammen aus einem Lauf, der %1 ist.</translation>
    </message>
    <message>
        <source> - NOT CONVERGED</source>
        <translation> - NICHT KONVERGIERT</translation>
    </message>
    <message>
        <source> - STOPPED EARLY</source>
        <translation> - VORZEITIG BEENDET</translation>
    </message>
    <message>
        <source>Read these figures with care: %1.</source>
        <translation>Diese Werte mit Vorsicht lesen: %1.</translation>
    </message>
    <message>
        <source>Catheter tip (node, or x,y,z in mm)</source>
        <translation>Katheterspitze (Knoten oder x,y,z in mm)</translation>
    </message>
    <message>
        <source>Tumour sphere (x, y, z, radius; mm)</source>
        <translation>Tumorkugel (x, y, z, Radius; mm)</translation>
    </message>
    <message>
        <source>Tumour label</source>
        <translation>Tumor-Label</translation>
    </message>
    <message>
        <source>Network file</source>
        <translation>Netzdatei</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Kontrollpunkte</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Distance along the centerline [mm]</source>
        <translation>Abstand entlang der Mittellinie [mm]</translation>
    </message>
    <message>
        <source>Equivalent diameter [mm]</source>
        <translation>Äquivalenter Durchmesser [mm]</translation>
    </message>
    <message>
        <source>diameter</source>
        <translation>Durchmesser</translation>
    </message>
    <message>
        <source>%1: not rendered (3D snapshots need a display; run under xvfb-run).</source>
        <translation>%1: nicht gerendert (3D-Aufnahmen brauchen eine Anzeige; unter xvfb-run ausführen).</translation>
    </message>
    <message>
        <source>%1: not rendered (%2).</source>
        <translation>%1: nicht gerendert (%2).</translation>
    </message>
    <message>
        <source>Perfused territory: the run had no liver label (simulate network --liver-label).</source>
        <translation>Perfundiertes Territorium: der Lauf hatte kein Leber-Label (simulate network --liver-label).</translation>
    </message>
    <message>
        <source>Perfused territory: the run again gave no territory.</source>
        <translation>Perfundiertes Territorium: die Wiederholung des Laufs ergab kein Territorium.</translation>
    </message>
    <message>
        <source>Perfused territory from the tip on the axial CT slice through the largest lesion (W 400 / L 40 HU; patient right on the left; the workstation&apos;s colours): green perfused liver, blue perfused tumour, red tumour not perfused, yellow margin not perfused, the liver not perfused unmarked (slice z = %1 mm)</source>
        <translation>Von der Spitze aus perfundiertes Territorium auf der axialen CT-Schicht durch die größte Läsion (W 400 / L 40 HU; Patient rechts im Bild links; Farben der Workstation): grün perfundierte Leber, blau perfundierter Tumor, rot nicht perfundierter Tumor, gelb nicht perfundierter Saum, nicht perfundierte Leber ohne Markierung (Schicht z = %1 mm)</translation>
    </message>
    <message>
        <source>Perfused territory: not drawn (%1).</source>
        <translation>Perfundiertes Territorium: nicht gezeichnet (%1).</translation>
    </message>
    <message>
        <source>Working angle: none for this run (the tip at the root, or working_angle 0).</source>
        <translation>Arbeitswinkel: keiner für diesen Lauf (Spitze an der Wurzel oder working_angle 0).</translation>
    </message>
    <message>
        <source>DSA-like view at the working angle (%1, %2 deg; patient supine, the head up): the tree the contrast opacifies, the path to the tip twice as dense (%3 mm pixels)</source>
        <translation>DSA-ähnliche Ansicht im Arbeitswinkel (%1, %2 Grad; Patient in Rückenlage, Kopf oben): der vom Kontrastmittel dargestellte Gefäßbaum, der Weg zur Spitze doppelt so dicht (%3-mm-Pixel)</translation>
    </message>
    <message>
        <source>cranial</source>
        <translation>kranial</translation>
    </message>
    <message>
        <source>caudal</source>
        <translation>kaudal</translation>
    </message>
    <message>
        <source>Diameter along the centerline (the segment of the maximum diameter)</source>
        <translation>Durchmesser entlang der Mittellinie (das Segment des maximalen Durchmessers)</translation>
    </message>
    <message>
        <source>repair threshold, men: 55 mm</source>
        <translation>Behandlungsschwelle, Männer: 55 mm</translation>
    </message>
    <message>
        <source>repair threshold, women: 50 mm</source>
        <translation>Behandlungsschwelle, Frauen: 50 mm</translation>
    </message>
    <message>
        <source>Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in women; this one is at or above both repair thresholds.</source>
        <translation>Eine Behandlung wird üblicherweise ab einem maximalen Durchmesser von 5,5 cm bei Männern und 5,0 cm bei Frauen erwogen; dieser liegt auf oder über beiden Schwellen.</translation>
    </message>
    <message>
        <source>Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in women; this one is at or above the threshold for women (5.0 cm), below the one for men (5.5 cm).</source>
        <translation>Eine Behandlung wird üblicherweise ab einem maximalen Durchmesser von 5,5 cm bei Männern und 5,0 cm bei Frauen erwogen; dieser liegt auf oder über der Schwelle für Frauen (5,0 cm), unter der für Männer (5,5 cm).</translation>
    </message>
    <message>
        <source>Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in women; this one is below both repair thresholds.</source>
        <translation>Eine Behandlung wird üblicherweise ab einem maximalen Durchmesser von 5,5 cm bei Männern und 5,0 cm bei Frauen erwogen; dieser liegt unter beiden Schwellen.</translation>
    </message>
    <message>
        <source>Maximum diameter, outer wall to outer wall (SVS)</source>
        <translation>Maximaler Durchmesser, Außenwand zu Außenwand (SVS)</translation>
    </message>
    <message>
        <source>Lumen diameter there (equivalent)</source>
        <translation>Lumendurchmesser dort (äquivalent)</translation>
    </message>
    <message>
        <source>Largest thrombus thickness</source>
        <translation>Größte Thrombusdicke</translation>
    </message>
    <message>
        <source>Sac volume</source>
        <translation>Volumen des Aneurysmasacks</translation>
    </message>
    <message>
        <source>Sac length</source>
        <translation>Länge des Aneurysmasacks</translation>
    </message>
    <message>
        <source>Neck diameter (outer, at the lowest renal artery)</source>
        <translation>Halsdurchmesser (außen, an der untersten Nierenarterie)</translation>
    </message>
    <message>
        <source>Neck length</source>
        <translation>Halslänge</translation>
    </message>
    <message>
        <source>Neck angulation</source>
        <translation>Halsangulation</translation>
    </message>
    <message>
        <source>Right common iliac diameter (outer)</source>
        <translation>Durchmesser der rechten A. iliaca communis (außen)</translation>
    </message>
    <message>
        <source>Left common iliac diameter (outer)</source>
        <translation>Durchmesser der linken A. iliaca communis (außen)</translation>
    </message>
    <message>
        <source>Wall thickness (assumed, not measured)</source>
        <translation>Wanddicke (angenommen, nicht gemessen)</translation>
    </message>
    <message>
        <source>The aneurysm sac (%1)</source>
        <translation>Der Aneurysmasack (%1)</translation>
    </message>
    <message>
        <source>Definitions.</source>
        <translation>Definitionen.</translation>
    </message>
    <message>
        <source>%1: %2.</source>
        <translation>%1: %2.</translation>
    </message>
    <message>
        <source>AAA rupture-risk review</source>
        <translation>AAA-Rupturrisiko-Beurteilung</translation>
    </message>
    <message>
        <source>The contrast lumen (cross-sections perpendicular to the centerline)</source>
        <translation>Das kontrastierte Lumen (Querschnitte senkrecht zur Mittellinie)</translation>
    </message>
    <message>
        <source>Maximum lumen diameter (equivalent)</source>
        <translation>Maximaler Lumendurchmesser (äquivalent)</translation>
    </message>
    <message>
        <source>Largest lumen caliper width</source>
        <translation>Größte Lumen-Caliperweite</translation>
    </message>
    <message>
        <source>These are lumen diameters; guidelines measure the aneurysm outer wall to outer wall with the thrombus (vascusim-cli sac). Against the lumen: %1</source>
        <translation>Dies sind Lumendurchmesser; Leitlinien messen das Aneurysma von Außenwand zu Außenwand einschließlich Thrombus (vascusim-cli sac). Bezogen auf das Lumen: %1</translation>
    </message>
    <message>
        <source>No centerlines and no sac: the maximum diameter was not measured.</source>
        <translation>Keine Mittellinien und kein Aneurysmasack: der maximale Durchmesser wurde nicht gemessen.</translation>
    </message>
    <message>
        <source>Wall stress at blood pressure (physiological protocol)</source>
        <translation>Wandspannung unter Blutdruck (physiologisches Protokoll)</translation>
    </message>
    <message>
        <source>Target blood pressure on the lumen</source>
        <translation>Ziel-Blutdruck auf dem Lumen</translation>
    </message>
    <message>
        <source>Pressure reached (the figures below are at this pressure)</source>
        <translation>Erreichter Druck (die folgenden Werte gelten bei diesem Druck)</translation>
    </message>
    <message>
        <source>Peak wall stress in the sac (von Mises, 99th percentile of its elements)</source>
        <translation>Maximale Wandspannung im Aneurysmasack (von Mises, 99. Perzentil seiner Elemente)</translation>
    </message>
    <message>
        <source>Peak wall stress in the sac (von Mises, largest nodal value)</source>
        <translation>Maximale Wandspannung im Aneurysmasack (von Mises, größter Knotenwert)</translation>
    </message>
    <message>
        <source>  its place: along the centerline below the lowest renal artery</source>
        <translation>  Ort: entlang der Mittellinie unterhalb der untersten Nierenarterie</translation>
    </message>
    <message>
        <source>  its clock position (seen from the feet; 12 anterior, 3 patient&apos;s left)</source>
        <translation>  Uhrzeigerposition (von den Füßen gesehen; 12 anterior, 3 links des Patienten)</translation>
    </message>
    <message>
        <source>Peak wall rupture index in the sac (stress / strength, 99th percentile)</source>
        <translation>Maximaler Wandrupturindex im Aneurysmasack (Spannung / Festigkeit, 99. Perzentil)</translation>
    </message>
    <message>
        <source>Peak wall rupture index in the sac (largest nodal value)</source>
        <translation>Maximaler Wandrupturindex im Aneurysmasack (größter Knotenwert)</translation>
    </message>
    <message>
        <source>  its clock position</source>
        <translation>  Uhrzeigerposition</translation>
    </message>
    <message>
        <source>Highest element stress on the whole wall (von Mises; a branch ostium or the iliac crotch may set it)</source>
        <translation>Höchste Elementspannung auf der gesamten Wand (von Mises; ein Abgangsostium oder die Iliakalgabel kann sie bestimmen)</translation>
    </message>
    <message>
        <source>Highest element stress on the whole wall (von Mises)</source>
        <translation>Höchste Elementspannung auf der gesamten Wand (von Mises)</translation>
    </message>
    <message>
        <source>  at x (patient LPS)</source>
        <translation>  bei x (Patienten-LPS)</translation>
    </message>
    <message>
        <source>  at y</source>
        <translation>  bei y</translation>
    </message>
    <message>
        <source>  at z</source>
        <translation>  bei z</translation>
    </message>
    <message>
        <source>Highest largest principal stress on the whole wall</source>
        <translation>Höchste größte Hauptspannung auf der gesamten Wand</translation>
    </message>
    <message>
        <source>Largest wall displacement</source>
        <translation>Größte Wandverschiebung</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <source> (the sac&apos;s neck outer diameter, or 20 mm without a sac)</source>
        <translation> (Außendurchmesser des Aneurysmahalses, ohne Aneurysmasack 20 mm)</translation>
    </message>
    <message>
        <source>the sac&apos;s neck outer diameter (20 mm without a sac)</source>
        <translation>der Außendurchmesser des Aneurysmahalses (ohne Aneurysmasack 20 mm)</translation>
    </message>
    <message>
        <source>inside the sac the thrombus crossed along each element&apos;s radius from the centerline and the outer wall-to-wall chord through the centerline there (the sac&apos;s labels), elsewhere the centerline diameter and a thrombus of %1 mm</source>
        <translation>im Aneurysmasack der Thrombus entlang des Radius jedes Elements von der Mittellinie aus und die Außenwand-zu-Außenwand-Sehne durch die Mittellinie dort (die Labels des Aneurysmasacks), andernorts der Mittellinien-Durchmesser und ein Thrombus von %1 mm</translation>
    </message>
    <message>
        <source>thrombus %1 mm (assumed), the centerline diameter</source>
        <translation>Thrombus %1 mm (angenommen), der Mittellinien-Durchmesser</translation>
    </message>
    <message>
        <source>Sex and family history were not both given, so no rupture index is reported (neither is assumed).</source>
        <translation>Geschlecht und Familienanamnese wurden nicht beide angegeben, daher wird kein Rupturindex berichtet (keines von beiden wird angenommen).</translation>
    </message>
    <message>
        <source>A rupture index of 1 means the stress reaches the estimated strength; it is given inside the aneurysm sac only (the regression was fitted to sacs).</source>
        <translation>Ein Rupturindex von 1 bedeutet, dass die Spannung die geschätzte Festigkeit erreicht; er wird nur innerhalb des Aneurysmasacks angegeben (die Regression wurde an Aneurysmasäcken angepasst).</translation>
    </message>
    <message>
        <source>No sac was measured (vascusim-cli sac), so no rupture index is given: the regression holds for the aneurysm sac only.</source>
        <translation>Es wurde kein Aneurysmasack gemessen (vascusim-cli sac), daher wird kein Rupturindex angegeben: die Regression gilt nur für den Aneurysmasack.</translation>
    </message>
    <message>
        <source>Strength model: Vande Geest et al. 2006 (wall strength from the local thrombus thickness, the local diameter over the non-aneurysmal reference, family history and sex), with %1; reference diameter %2, sex %3, family history of AAA %4. %5</source>
        <translation>Festigkeitsmodell: Vande Geest et al. 2006 (Wandfestigkeit aus lokaler Thrombusdicke, lokalem Durchmesser bezogen auf die nicht-aneurysmatische Referenz, Familienanamnese und Geschlecht), mit %1; Referenzdurchmesser %2, Geschlecht %3, AAA in der Familienanamnese %4. %5</translation>
    </message>
    <message>
        <source>female</source>
        <translation>weiblich</translation>
    </message>
    <message>
        <source>male</source>
        <translation>männlich</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>Wall stress (von Mises, kPa; the elements&apos; values averaged to the surface points) at blood pressure, seen from the front; PWS and PWRI mark the sac&apos;s nodal maxima (clock position seen from the feet, 12 h anterior)</source>
        <translation>Wandspannung (von Mises, kPa; die Elementwerte auf die Oberflächenpunkte gemittelt) unter Blutdruck, Ansicht von vorn; PWS und PWRI markieren die Knotenmaxima des Aneurysmasacks (Uhrzeigerposition von den Füßen gesehen, 12 Uhr anterior)</translation>
    </message>
    <message>
        <source>von Mises [kPa]</source>
        <translation>von Mises [kPa]</translation>
    </message>
    <message>
        <source>The physiological wall-stress run was not made for this study.</source>
        <translation>Der physiologische Wandspannungslauf wurde für diese Studie nicht durchgeführt.</translation>
    </message>
    <message>
        <source>Tearing (thesis protocol: pressure ramp on the middle of the vessel)</source>
        <translation>Einreißen (Protokoll der Dissertation: Druckrampe auf die Gefäßmitte)</translation>
    </message>
    <message>
        <source>Pressure at the first tear (-1: none)</source>
        <translation>Druck beim ersten Riss (-1: keiner)</translation>
    </message>
    <message>
        <source>Torn elements</source>
        <translation>Gerissene Elemente</translation>
    </message>
    <message>
        <source>Fracture entropy</source>
        <translation>Bruchentropie</translation>
    </message>
    <message>
        <source>Pressure at the end of the run</source>
        <translation>Druck am Ende des Laufs</translation>
    </message>
    <message>
        <source>Research protocol: the thesis&apos;s ramp pressures (by default 8-12 MPa, about 600 times systolic) are not physiological, and its tear strength is no measured wall strength; these figures reproduce the thesis&apos;s experiment and say nothing about this patient&apos;s rupture risk.</source>
        <translation>Forschungsprotokoll: die Rampendrücke der Dissertation (standardmäßig 8-12 MPa, etwa das 600-Fache des systolischen Drucks) sind nicht physiologisch, und ihre Reißfestigkeit ist keine gemessene Wandfestigkeit; diese Werte reproduzieren das Experiment der Dissertation und sagen nichts über das Rupturrisiko dieses Patienten aus.</translation>
    </message>
    <message>
        <source>Tearing was quasi-static: the wall in equilibrium at each pressure, the onset bracketed by bisection to 0.5 %, one element released per equilibrium.</source>
        <translation>Das Einreißen war quasistatisch: die Wand bei jedem Druck im Gleichgewicht, der Beginn durch Bisektion auf 0,5 % eingegrenzt, ein Element je Gleichgewicht freigegeben.</translation>
    </message>
    <message>
        <source>Tearing followed the thesis&apos;s damped ramp: the wall lags the load, so the onset pressure depends on the ramp&apos;s rate.</source>
        <translation>Das Einreißen folgte der gedämpften Rampe der Dissertation: die Wand folgt der Last verzögert, daher hängt der Einrissdruck von der Rampengeschwindigkeit ab.</translation>
    </message>
    <message>
        <source>The thesis tearing protocol was not run for this study.</source>
        <translation>Das Einreißprotokoll der Dissertation wurde für diese Studie nicht ausgeführt.</translation>
    </message>
    <message>
        <source>VascuSim planning report</source>
        <translation>VascuSim-Planungsbericht</translation>
    </message>
    <message>
        <source>AAA rupture-risk review: the study has no AAA sac (vascusim-cli sac) and no wall-mechanics run (simulate fem).</source>
        <translation>AAA-Rupturrisiko-Beurteilung: die Studie hat keinen AAA-Sack (vascusim-cli sac) und keinen Wandmechaniklauf (simulate fem).</translation>
    </message>
    <message>
        <source>Stenosis / blockage: no segment of the centerlines narrows by 40 % or more, and the study has no blood-flow run (velocity ratios, pressure drop).</source>
        <translation>Stenose / Verschluss: kein Segment der Mittellinien verengt sich um 40 % oder mehr, und die Studie hat keinen Blutflusslauf (Geschwindigkeitsverhältnisse, Druckabfall).</translation>
    </message>
    <message>
        <source>Chemoembolization: the study has no drug-delivery run (simulate network).</source>
        <translation>Chemoembolisation: die Studie hat keinen Lauf zur Wirkstoffgabe (simulate network).</translation>
    </message>
    <message>
        <source> (posterior)</source>
        <translation> (posterior)</translation>
    </message>
    <message>
        <source>Surgical smoke: stable fluids on a MAC grid (thesis ch. 7; semi-Lagrangian velocity advection, conservative limited transport of the smoke, Boussinesq buoyancy, vorticity confinement and vortex particles), the pressure projection by multigrid-preconditioned conjugate gradients; single precision on the CPU.</source>
        <translation>Chirurgischer Rauch: Stable Fluids auf einem MAC-Gitter (Dissertation Kap. 7; semi-Lagrange-Advektion der Geschwindigkeit, konservativer begrenzter Transport des Rauchs, Boussinesq-Auftrieb, Vorticity Confinement und Wirbelpartikel), die Druckprojektion mit Mehrgitter-vorkonditionierten konjugierten Gradienten; einfache Genauigkeit auf der CPU.</translation>
    </message>
    <message>
        <source>Endoscopic vessel harvesting: a CO2 tunnel drawn around 60 mm of the study&apos;s longest centerline segment (a pre-operative CT shows no tunnel), the cautery&apos;s contact on the vessel&apos;s anterior wall, smoke from 9 s after contact (thesis ch. 7), the endoscope 25 mm back in the tunnel.</source>
        <translation>Endoskopische Gefäßentnahme: ein CO2-Tunnel um 60 mm des längsten Mittelliniensegments der Studie gelegt (ein präoperatives CT zeigt keinen Tunnel), der Kontakt des Kauters an der Vorderwand des Gefäßes, Rauch ab 9 s nach dem Kontakt (Dissertation Kap. 7), das Endoskop 25 mm zurück im Tunnel.</translation>
    </message>
    <message>
        <source>Liver ablation under laparoscopy: an insufflated dome over the liver (the study&apos;s liver label, or a box phantom without one), the probe&apos;s smoke at the liver&apos;s surface, the insufflator a vent in the roof, a suction port beside the probe, the laparoscope looking down at the site.</source>
        <translation>Leberablation unter Laparoskopie: eine insufflierte Kuppel über der Leber (das Leber-Label der Studie oder ohne dieses ein Quader-Phantom), der Rauch der Sonde an der Leberoberfläche, der Insufflator eine Öffnung im Dach, ein Absaugport neben der Sonde, das Laparoskop blickt von oben auf die Stelle.</translation>
    </message>
    <message>
        <source>The thesis demo: a 1 m box open at the top, smoke rising from the floor, a ball dropped through it.</source>
        <translation>Die Demo der Dissertation: ein oben offener Kasten von 1 m, vom Boden aufsteigender Rauch, eine hindurchfallende Kugel.</translation>
    </message>
    <message>
        <source>Surgical smoke (illustrative scene)</source>
        <translation>Chirurgischer Rauch (veranschaulichende Szene)</translation>
    </message>
    <message>
        <source>The scene is illustrative: its geometry is synthetic and the smoke&apos;s emission is an assumption; the figures show how the smoke spreads and clears, not this patient&apos;s case.</source>
        <translation>Die Szene ist veranschaulichend: ihre Geometrie ist synthetisch und die Rauchemission eine Annahme; die Werte zeigen, wie sich der Rauch ausbreitet und abzieht, nicht den Fall dieses Patienten.</translation>
    </message>
    <message>
        <source>The endoscope&apos;s view</source>
        <translation>Die Sicht des Endoskops</translation>
    </message>
    <message>
        <source>Time to 50 % of the view obscured</source>
        <translation>Zeit bis 50 % der Sicht verdeckt sind</translation>
    </message>
    <message>
        <source>Time to 90 % of the view obscured</source>
        <translation>Zeit bis 90 % der Sicht verdeckt sind</translation>
    </message>
    <message>
        <source>Largest share of the view obscured</source>
        <translation>Größter verdeckter Anteil der Sicht</translation>
    </message>
    <message>
        <source>Share of the view obscured at the end</source>
        <translation>Verdeckter Anteil der Sicht am Ende</translation>
    </message>
    <message>
        <source>Smoke in the cavity at the end</source>
        <translation>Rauch im Hohlraum am Ende</translation>
    </message>
    <message>
        <source>Time to clear after the suction starts (under 10 % obscured)</source>
        <translation>Zeit bis zur freien Sicht nach Beginn der Absaugung (unter 10 % verdeckt)</translation>
    </message>
    <message>
        <source>Smoke removed in the suction&apos;s first 10 s</source>
        <translation>In den ersten 10 s der Absaugung entfernter Rauch</translation>
    </message>
    <message>
        <source>A pixel of the endoscope&apos;s view is obscured when less than %1 % of the light from the scene passes the smoke (Beer-Lambert, the mass extinction coefficient %2 m^2/g: Mulholland &amp; Croarkin 2000).</source>
        <translation>Ein Pixel der Endoskopsicht gilt als verdeckt, wenn weniger als %1 % des Lichts der Szene den Rauch durchdringen (Beer-Lambert, Massenextinktionskoeffizient %2 m^2/g: Mulholland &amp; Croarkin 2000).</translation>
    </message>
    <message>
        <source>Not reached within the run: %1.</source>
        <translation>Im Lauf nicht erreicht: %1.</translation>
    </message>
    <message>
        <source>The suction&apos;s flow is calibrated to a published measurement (proximal evacuation removing about 85 % of the smoke in 10 s, Chou 2024): a calibration, not a validation.</source>
        <translation>Der Absaugfluss ist an einer veröffentlichten Messung kalibriert (proximale Absaugung entfernt etwa 85 % des Rauchs in 10 s, Chou 2024): eine Kalibrierung, keine Validierung.</translation>
    </message>
    <message>
        <source>The endoscope&apos;s view obscured by the smoke over time</source>
        <translation>Die durch den Rauch verdeckte Sicht des Endoskops über die Zeit</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>View obscured [%]</source>
        <translation>Verdeckte Sicht [%]</translation>
    </message>
    <message>
        <source>obscured</source>
        <translation>verdeckt</translation>
    </message>
    <message>
        <source>50 %</source>
        <translation>50 %</translation>
    </message>
    <message>
        <source>90 %</source>
        <translation>90 %</translation>
    </message>
    <message>
        <source>Surgical smoke: the study has no smoke run (simulate smoke).</source>
        <translation>Chirurgischer Rauch: die Studie hat keinen Rauchlauf (simulate smoke).</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Szenario</translation>
    </message>
    <message>
        <source>Wall loads on the lumen surface (the same run and window; tau_w: the walls&apos; friction on the particles next to them)</source>
        <translation>Wandlasten auf der Lumenoberfläche (derselbe Lauf und dasselbe Zeitfenster; tau_w: die Reibung der Wand an den wandnahen Partikeln)</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>k. A.</translation>
    </message>
    <message>
        <source>Wall mechanics: quadratic (10-node) tetrahedral FEM, the Raghavan &amp; Vorp 2000 hyperelastic AAA wall (nearly incompressible), the blood pressure as a follower load on the lumen, ends held; the static equilibrium by Newton&apos;s method (GMRES preconditioned by a sparse Cholesky or LU factorisation) to the force tolerance. The imaged geometry is taken as unloaded (CT shows the vessel at its pressure); the intraluminal thrombus, where the wall mesh has it, as its own layer (Wang et al. 2001).</source>
        <translation>Wandmechanik: FEM mit quadratischen (10-Knoten-)Tetraedern, die hyperelastische AAA-Wand nach Raghavan &amp; Vorp 2000 (nahezu inkompressibel), der Blutdruck als mitgehende Last auf dem Lumen, Enden gehalten; das statische Gleichgewicht nach dem Newton-Verfahren (GMRES, vorkonditioniert mit einer dünnbesetzten Cholesky- oder LU-Zerlegung) bis zur Krafttoleranz. Die abgebildete Geometrie gilt als unbelastet (das CT zeigt das Gefäß unter seinem Druck); der intraluminale Thrombus, wo das Wandnetz ihn enthält, als eigene Schicht (Wang et al. 2001).</translation>
    </message>
</context>
<context>
    <name>vsim::Error</name>
    <message>
        <source>the series belongs to another patient than the study (Patient ID differs); import it into a study of its own</source>
        <translation>die Serie gehört zu einem anderen Patienten als die Studie (Patienten-ID verschieden); importieren Sie sie in eine eigene Studie</translation>
    </message>
    <message>
        <source>the needle&apos;s bore, the generation rate and the box&apos;s depth must be positive, the box&apos;s margin not negative</source>
        <translation>Kanülenbohrung, Erzeugungsrate und Tiefe des Behälters müssen positiv sein, der Rand des Behälters darf nicht negativ sein</translation>
    </message>
    <message>
        <source>cannot write the run file</source>
        <translation>die Laufdatei kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>the drug run records no centerlines to run again from</source>
        <translation>der Wirkstofflauf verzeichnet keine Mittellinien, von denen aus er erneut laufen könnte</translation>
    </message>
    <message>
        <source>artifact</source>
        <translation>Artefakt</translation>
    </message>
    <message>
        <source>cannot create the run folder</source>
        <translation>der Ordner des Laufs kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>folder</source>
        <translation>Ordner</translation>
    </message>
    <message>
        <source>cannot write metrics.json</source>
        <translation>metrics.json kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>the wall-load surface has no TAWSS</source>
        <translation>die Wandlast-Oberfläche hat keine TAWSS</translation>
    </message>
    <message>
        <source>no vertex of the wall-load surface was sampled</source>
        <translation>kein Eckpunkt der Wandlast-Oberfläche wurde abgetastet</translation>
    </message>
    <message>
        <source>not a centerlines artifact</source>
        <translation>kein Mittellinien-Artefakt</translation>
    </message>
    <message>
        <source>segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>a segment&apos;s name cannot be empty</source>
        <translation>der Name eines Segments darf nicht leer sein</translation>
    </message>
    <message>
        <source>the evh scenario places its tunnel around a vessel: the study has no centerlines (vascusim-cli centerlines)</source>
        <translation>das EVH-Szenario legt seinen Tunnel um ein Gefäß: die Studie hat keine Mittellinien (vascusim-cli centerlines)</translation>
    </message>
    <message>
        <source>the study&apos;s centerlines have no segment for the evh tunnel</source>
        <translation>die Mittellinien der Studie haben kein Segment für den EVH-Tunnel</translation>
    </message>
    <message>
        <source>not a translation catalogue (.qm)</source>
        <translation>kein Übersetzungskatalog (.qm)</translation>
    </message>
    <message>
        <source>a sheet needs a positive size, a cell size and at least 0.05 mm thickness</source>
        <translation>eine Schicht braucht eine positive Größe, eine Zellgröße und mindestens 0,05 mm Dicke</translation>
    </message>
    <message>
        <source>scaledSum: x and y differ in length</source>
        <translation>scaledSum: x und y sind verschieden lang</translation>
    </message>
    <message>
        <source>no CUDA device: run the wall solver on the CPU (--backend cpu)</source>
        <translation>kein CUDA-Gerät: rechnen Sie die Wand auf der CPU (--backend cpu)</translation>
    </message>
    <message>
        <source>the CUDA backend runs the co-rotational linear model only: run St. Venant-Kirchhoff on the CPU (--backend cpu)</source>
        <translation>das CUDA-Backend rechnet nur das korotierende lineare Modell: rechnen Sie St. Venant-Kirchhoff auf der CPU (--backend cpu)</translation>
    </message>
    <message>
        <source>the smoke&apos;s CUDA backend needs a CUDA device, and there is none</source>
        <translation>das CUDA-Backend des Rauchs braucht ein CUDA-Gerät, und es gibt keines</translation>
    </message>
    <message>
        <source>the smoke&apos;s CUDA backend takes grids of fewer than 2^31 cells</source>
        <translation>das CUDA-Backend des Rauchs nimmt Gitter mit weniger als 2^31 Zellen</translation>
    </message>
    <message>
        <source>the smoke&apos;s CUDA backend was made for another grid</source>
        <translation>das CUDA-Backend des Rauchs wurde für ein anderes Gitter angelegt</translation>
    </message>
    <message>
        <source>no CUDA device: run the SPH solver on the CPU (--backend cpu)</source>
        <translation>kein CUDA-Gerät: rechnen Sie SPH auf der CPU (--backend cpu)</translation>
    </message>
    <message>
        <source>the CUDA SPH backend runs no periodic axes or tracer absorption yet: run this case on the CPU (--backend cpu)</source>
        <translation>das CUDA-SPH-Backend rechnet noch keine periodischen Achsen und keine Tracer-Aufnahme: rechnen Sie diesen Fall auf der CPU (--backend cpu)</translation>
    </message>
    <message>
        <source>cancelled by the user</source>
        <translation>vom Benutzer abgebrochen</translation>
    </message>
    <message>
        <source>image volume adopted an empty buffer</source>
        <translation>das Bildvolumen hat einen leeren Puffer übernommen</translation>
    </message>
    <message>
        <source>--rescale needs a finite, non-zero slope and a finite intercept</source>
        <translation>--rescale braucht eine endliche Steigung ungleich null und einen endlichen Achsenabschnitt</translation>
    </message>
    <message>
        <source>option</source>
        <translation>Option</translation>
    </message>
    <message>
        <source>cannot write into the output folder</source>
        <translation>in den Ausgabeordner kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>the output path is a file, not a folder; VascuSim does not replace it</source>
        <translation>der Ausgabepfad ist eine Datei, kein Ordner; VascuSim ersetzt sie nicht</translation>
    </message>
    <message>
        <source>path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <source>the output folder holds files VascuSim did not write; choose a new or empty folder</source>
        <translation>der Ausgabeordner enthält Dateien, die VascuSim nicht geschrieben hat; wählen Sie einen neuen oder leeren Ordner</translation>
    </message>
    <message>
        <source>the output path is a folder; VascuSim writes a file there only where nothing is</source>
        <translation>der Ausgabepfad ist ein Ordner; VascuSim schreibt eine Datei nur dorthin, wo nichts ist</translation>
    </message>
    <message>
        <source>the output file exists; give --overwrite to replace it</source>
        <translation>die Ausgabedatei existiert; geben Sie --overwrite an, um sie zu ersetzen</translation>
    </message>
    <message>
        <source>the output path is not a regular file; VascuSim does not replace it</source>
        <translation>der Ausgabepfad ist keine reguläre Datei; VascuSim ersetzt ihn nicht</translation>
    </message>
    <message>
        <source>parameter declared twice</source>
        <translation>Parameter doppelt deklariert</translation>
    </message>
    <message>
        <source>key</source>
        <translation>Schlüssel</translation>
    </message>
    <message>
        <source>parameter default outside its declared range</source>
        <translation>Standardwert des Parameters außerhalb seines Bereichs</translation>
    </message>
    <message>
        <source>default</source>
        <translation>Standardwert</translation>
    </message>
    <message>
        <source>range</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <source>known parameters</source>
        <translation>bekannte Parameter</translation>
    </message>
    <message>
        <source>text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>the principal axis of no points</source>
        <translation>die Hauptachse von null Punkten</translation>
    </message>
    <message>
        <source>skeleton edge refers to a missing node</source>
        <translation>eine Skelettkante verweist auf einen fehlenden Knoten</translation>
    </message>
    <message>
        <source>skeleton edge has fewer than two points</source>
        <translation>eine Skelettkante hat weniger als zwei Punkte</translation>
    </message>
    <message>
        <source>skeleton edge has point, voxel and radius lists of different lengths</source>
        <translation>eine Skelettkante hat Punkt-, Voxel- und Radiuslisten verschiedener Länge</translation>
    </message>
    <message>
        <source>skeleton edge has a radius that is not positive</source>
        <translation>eine Skelettkante hat einen nicht positiven Radius</translation>
    </message>
    <message>
        <source>tetrahedron refers to a missing point</source>
        <translation>ein Tetraeder verweist auf einen fehlenden Punkt</translation>
    </message>
    <message>
        <source>element</source>
        <translation>Element</translation>
    </message>
    <message>
        <source>point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <source>inverted or degenerate tetrahedron</source>
        <translation>umgestülpter oder entarteter Tetraeder</translation>
    </message>
    <message>
        <source>point field length differs from the point count</source>
        <translation>die Länge des Punktfelds weicht von der Punktzahl ab</translation>
    </message>
    <message>
        <source>field</source>
        <translation>Feld</translation>
    </message>
    <message>
        <source>cell field length differs from the element count</source>
        <translation>die Länge des Zellfelds weicht von der Elementzahl ab</translation>
    </message>
    <message>
        <source>triangle refers to a missing point</source>
        <translation>ein Dreieck verweist auf einen fehlenden Punkt</translation>
    </message>
    <message>
        <source>triangle</source>
        <translation>Dreieck</translation>
    </message>
    <message>
        <source>triangle repeats a point</source>
        <translation>ein Dreieck wiederholt einen Punkt</translation>
    </message>
    <message>
        <source>node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>an ROI takes two corner points</source>
        <translation>eine ROI braucht zwei Eckpunkte</translation>
    </message>
    <message>
        <source>volume dimension is not positive</source>
        <translation>eine Volumenabmessung ist nicht positiv</translation>
    </message>
    <message>
        <source>axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>voxel spacing must be positive and finite (mm)</source>
        <translation>der Voxelabstand muss positiv und endlich sein (mm)</translation>
    </message>
    <message>
        <source>spacing</source>
        <translation>Abstand</translation>
    </message>
    <message>
        <source>volume origin is not finite</source>
        <translation>der Ursprung des Volumens ist nicht endlich</translation>
    </message>
    <message>
        <source>direction matrix is not orthonormal</source>
        <translation>die Richtungsmatrix ist nicht orthonormal</translation>
    </message>
    <message>
        <source>deviation</source>
        <translation>Abweichung</translation>
    </message>
    <message>
        <source>the AAA phantom&apos;s aneurysm is smaller than 1.5 times its neck; choose a larger --max-diameter</source>
        <translation>das Aneurysma des AAA-Phantoms ist kleiner als das 1,5-Fache seines Halses; wählen Sie einen größeren --max-diameter</translation>
    </message>
    <message>
        <source>unknown transfer syntax</source>
        <translation>unbekannte Transfersyntax</translation>
    </message>
    <message>
        <source>cannot set a DICOM attribute</source>
        <translation>ein DICOM-Attribut kann nicht gesetzt werden</translation>
    </message>
    <message>
        <source>tag</source>
        <translation>Tag</translation>
    </message>
    <message>
        <source>reason</source>
        <translation>Grund</translation>
    </message>
    <message>
        <source>cannot create a DICOM sequence item</source>
        <translation>ein DICOM-Sequenzelement kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>HU value outside -1024..3071 cannot be stored in 12 unsigned bits</source>
        <translation>ein HU-Wert außerhalb von -1024..3071 lässt sich nicht in 12 vorzeichenlosen Bits speichern</translation>
    </message>
    <message>
        <source>cannot encode the pixel data</source>
        <translation>die Pixeldaten können nicht kodiert werden</translation>
    </message>
    <message>
        <source>cannot write DICOM file</source>
        <translation>die DICOM-Datei kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>the pixels and the slice stack of a CT series disagree</source>
        <translation>Pixel und Schichtstapel einer CT-Serie stimmen nicht überein</translation>
    </message>
    <message>
        <source>file name prefix must have at most 2 characters (8-character DICOMDIR names)</source>
        <translation>das Dateinamen-Präfix darf höchstens 2 Zeichen haben (8-stellige DICOMDIR-Namen)</translation>
    </message>
    <message>
        <source>cannot create the output folder</source>
        <translation>der Ausgabeordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>DICOM image has no rows or columns</source>
        <translation>das DICOM-Bild hat keine Zeilen oder Spalten</translation>
    </message>
    <message>
        <source>inconsistent Bits Stored / High Bit</source>
        <translation>widersprüchliche Bits Stored / High Bit</translation>
    </message>
    <message>
        <source>frame index out of range</source>
        <translation>Frame-Index außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>frame</source>
        <translation>Frame</translation>
    </message>
    <message>
        <source>pixel data is shorter than the image it describes (truncated file?)</source>
        <translation>die Pixeldaten sind kürzer als das Bild, das sie beschreiben (abgeschnittene Datei?)</translation>
    </message>
    <message>
        <source>JPEG 2000 code stream size differs from the image&apos;s rows and columns</source>
        <translation>die Größe des JPEG-2000-Codestroms weicht von Zeilen und Spalten des Bildes ab</translation>
    </message>
    <message>
        <source>JPEG 2000 pixel data has no code stream header</source>
        <translation>die JPEG-2000-Pixeldaten haben keinen Codestrom-Header</translation>
    </message>
    <message>
        <source>compressed pixel data has no fragments</source>
        <translation>die komprimierten Pixeldaten haben keine Fragmente</translation>
    </message>
    <message>
        <source>compressed pixel data fragment unreadable</source>
        <translation>ein Fragment der komprimierten Pixeldaten ist nicht lesbar</translation>
    </message>
    <message>
        <source>multi-frame JPEG 2000 with several fragments per frame is not supported</source>
        <translation>Mehrbild-JPEG-2000 mit mehreren Fragmenten je Frame wird nicht unterstützt</translation>
    </message>
    <message>
        <source>damaged JPEG stream: no start of image</source>
        <translation>beschädigter JPEG-Strom: kein Bildanfang</translation>
    </message>
    <message>
        <source>damaged JPEG stream: marker expected</source>
        <translation>beschädigter JPEG-Strom: Marker erwartet</translation>
    </message>
    <message>
        <source>damaged JPEG stream: ends in fill bytes</source>
        <translation>beschädigter JPEG-Strom: endet in Füllbytes</translation>
    </message>
    <message>
        <source>damaged JPEG stream: unexpected marker before the scan</source>
        <translation>beschädigter JPEG-Strom: unerwarteter Marker vor dem Scan</translation>
    </message>
    <message>
        <source>damaged JPEG stream: truncated marker segment</source>
        <translation>beschädigter JPEG-Strom: abgeschnittenes Markersegment</translation>
    </message>
    <message>
        <source>damaged JPEG stream: bad marker segment length</source>
        <translation>beschädigter JPEG-Strom: falsche Länge eines Markersegments</translation>
    </message>
    <message>
        <source>damaged JPEG stream: scan without a frame header</source>
        <translation>beschädigter JPEG-Strom: Scan ohne Frame-Header</translation>
    </message>
    <message>
        <source>cannot decode the JPEG 2000 code stream</source>
        <translation>der JPEG-2000-Codestrom kann nicht dekodiert werden</translation>
    </message>
    <message>
        <source>cannot decompress the pixel data</source>
        <translation>die Pixeldaten können nicht dekomprimiert werden</translation>
    </message>
    <message>
        <source>transfer_syntax</source>
        <translation>Transfersyntax</translation>
    </message>
    <message>
        <source>pixel data missing</source>
        <translation>Pixeldaten fehlen</translation>
    </message>
    <message>
        <source>pixel data longer than the file (damaged length or truncated file)</source>
        <translation>Pixeldaten länger als die Datei (beschädigte Länge oder abgeschnittene Datei)</translation>
    </message>
    <message>
        <source>cannot read the pixel data</source>
        <translation>die Pixeldaten können nicht gelesen werden</translation>
    </message>
    <message>
        <source>cannot open the file</source>
        <translation>die Datei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>not a greyscale image</source>
        <translation>kein Graustufenbild</translation>
    </message>
    <message>
        <source>photometric</source>
        <translation>photometrische Interpretation</translation>
    </message>
    <message>
        <source>damaged or truncated DICOM file</source>
        <translation>beschädigte oder abgeschnittene DICOM-Datei</translation>
    </message>
    <message>
        <source>decodeFramesToHu: one output per frame expected</source>
        <translation>decodeFramesToHu: eine Ausgabe je Frame erwartet</translation>
    </message>
    <message>
        <source>needed_bytes</source>
        <translation>benötigte Bytes</translation>
    </message>
    <message>
        <source>available_bytes</source>
        <translation>verfügbare Bytes</translation>
    </message>
    <message>
        <source>cannot read the DICOMDIR</source>
        <translation>das DICOMDIR kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>the DICOMDIR has no directory records</source>
        <translation>das DICOMDIR hat keine Verzeichniseinträge</translation>
    </message>
    <message>
        <source>no such file or folder</source>
        <translation>keine solche Datei und kein solcher Ordner</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s per-frame functional groups do not match its number of frames</source>
        <translation>die Per-Frame Functional Groups des DICOM SEG passen nicht zu seiner Frame-Zahl</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s frames have several orientations: not one volume</source>
        <translation>die Frames des DICOM SEG haben mehrere Orientierungen: kein einzelnes Volumen</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s frames are shifted within their planes: not one volume</source>
        <translation>die Frames des DICOM SEG sind in ihren Ebenen verschoben: kein einzelnes Volumen</translation>
    </message>
    <message>
        <source>the DICOM SEG has no readable pixel data (compressed SEG objects are not supported)</source>
        <translation>das DICOM SEG hat keine lesbaren Pixeldaten (komprimierte SEG-Objekte werden nicht unterstützt)</translation>
    </message>
    <message>
        <source>the label cannot be written as a DICOM SEG (empty, or over 65535 pixels a row)</source>
        <translation>das Label kann nicht als DICOM SEG geschrieben werden (leer oder über 65535 Pixel je Zeile)</translation>
    </message>
    <message>
        <source>the label has no labelled voxel to write as a DICOM SEG</source>
        <translation>das Label hat kein markiertes Voxel, das als DICOM SEG geschrieben werden könnte</translation>
    </message>
    <message>
        <source>writing the DICOM SEG failed at the referenced series</source>
        <translation>das Schreiben des DICOM SEG ist an der referenzierten Serie gescheitert</translation>
    </message>
    <message>
        <source>a retrieve needs the study&apos;s instance UID</source>
        <translation>ein Abruf braucht die Instance UID der Studie</translation>
    </message>
    <message>
        <source>a series query needs the study&apos;s instance UID</source>
        <translation>eine Serienabfrage braucht die Instance UID der Studie</translation>
    </message>
    <message>
        <source>nothing to store: name one or more DICOM files</source>
        <translation>nichts zu senden: nennen Sie eine oder mehrere DICOM-Dateien</translation>
    </message>
    <message>
        <source>phantom size must be 8..4096 voxels per axis</source>
        <translation>die Phantomgröße muss 8..4096 Voxel je Achse betragen</translation>
    </message>
    <message>
        <source>phantom spacing must be 0.05..20 mm</source>
        <translation>der Phantom-Voxelabstand muss 0,05..20 mm betragen</translation>
    </message>
    <message>
        <source>phantom noise must be 0..500 HU</source>
        <translation>das Phantomrauschen muss 0..500 HU betragen</translation>
    </message>
    <message>
        <source>phantom blur must be at most 10 mm</source>
        <translation>die Phantomunschärfe darf höchstens 10 mm betragen</translation>
    </message>
    <message>
        <source>aneurysm diameter must be 20..120 mm</source>
        <translation>der Aneurysmadurchmesser muss 20..120 mm betragen</translation>
    </message>
    <message>
        <source>phantom PSF FWHM must be 0.1..5 mm</source>
        <translation>die Halbwertsbreite der Phantom-PSF muss 0,1..5 mm betragen</translation>
    </message>
    <message>
        <source>stenosis must be 0..95 percent</source>
        <translation>die Stenose muss 0..95 Prozent betragen</translation>
    </message>
    <message>
        <source>the second stenosis must be 0..95 percent</source>
        <translation>die zweite Stenose muss 0..95 Prozent betragen</translation>
    </message>
    <message>
        <source>the vessel diameter must be 1..40 mm</source>
        <translation>der Gefäßdurchmesser muss 1..40 mm betragen</translation>
    </message>
    <message>
        <source>the stenosis length must be 2..100 mm (0: drawn from the seed)</source>
        <translation>die Stenoselänge muss 2..100 mm betragen (0: aus dem Startwert gezogen)</translation>
    </message>
    <message>
        <source>cannot write truth.json</source>
        <translation>truth.json kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>the series has images without Image Position/Orientation (Patient): it cannot be placed in the patient frame</source>
        <translation>die Serie hat Bilder ohne Image Position/Orientation (Patient): sie lässt sich nicht ins Patientenkoordinatensystem legen</translation>
    </message>
    <message>
        <source>the series has images without Pixel Spacing</source>
        <translation>die Serie hat Bilder ohne Pixel Spacing</translation>
    </message>
    <message>
        <source>the series has no images</source>
        <translation>die Serie hat keine Bilder</translation>
    </message>
    <message>
        <source>the lumen label is not on the CT&apos;s grid</source>
        <translation>das Lumen-Label liegt nicht auf dem Gitter des CT</translation>
    </message>
    <message>
        <source>the wall thickness must be 0..5 mm</source>
        <translation>die Wanddicke muss 0..5 mm betragen</translation>
    </message>
    <message>
        <source>no abdominal aorta found (a round contrast-filled cross-section in front of the spine in three neighbouring slices): give a point inside it with --seed x,y,z</source>
        <translation>keine Bauchaorta gefunden (ein runder kontrastgefüllter Querschnitt vor der Wirbelsäule in drei benachbarten Schichten): geben Sie mit --seed x,y,z einen Punkt darin an</translation>
    </message>
    <message>
        <source>the label holds no aorta-sized cross-section (50 mm2 or more): segment the aorta first (vascusim-cli segment --target aorta)</source>
        <translation>das Label enthält keinen Querschnitt von Aortengröße (50 mm2 oder mehr): segmentieren Sie zuerst die Aorta (vascusim-cli segment --target aorta)</translation>
    </message>
    <message>
        <source>the skeleton is empty: run the skeleton step first</source>
        <translation>das Skelett ist leer: führen Sie zuerst den Skelettschritt aus</translation>
    </message>
    <message>
        <source>the centerline step must be positive</source>
        <translation>die Schrittweite der Mittellinie muss positiv sein</translation>
    </message>
    <message>
        <source>the guided segmentation needs at least one include point inside the vessel</source>
        <translation>die geführte Segmentierung braucht mindestens einen Einschlusspunkt im Gefäß</translation>
    </message>
    <message>
        <source>at most 250 include and exclude points</source>
        <translation>höchstens 250 Einschluss- und Ausschlusspunkte</translation>
    </message>
    <message>
        <source>the points grew no vessel: pick them inside the contrast-filled lumen</source>
        <translation>aus den Punkten ist kein Gefäß gewachsen: setzen Sie sie in das kontrastgefüllte Lumen</translation>
    </message>
    <message>
        <source>cannot merge a paint and an erase stroke</source>
        <translation>ein Mal- und ein Radierstrich lassen sich nicht zusammenführen</translation>
    </message>
    <message>
        <source>there is no label to edit</source>
        <translation>es gibt kein Label zum Bearbeiten</translation>
    </message>
    <message>
        <source>the brush needs a positive radius</source>
        <translation>der Pinsel braucht einen positiven Radius</translation>
    </message>
    <message>
        <source>the brush needs a plane</source>
        <translation>der Pinsel braucht eine Ebene</translation>
    </message>
    <message>
        <source>the label is empty: segment the vessels first</source>
        <translation>das Label ist leer: segmentieren Sie zuerst die Gefäße</translation>
    </message>
    <message>
        <source>the liver label holds no voxel near the points</source>
        <translation>das Leber-Label hat kein Voxel in der Nähe der Punkte</translation>
    </message>
    <message>
        <source>place at least one point inside the lesion</source>
        <translation>setzen Sie mindestens einen Punkt in die Läsion</translation>
    </message>
    <message>
        <source>a point lies outside the CT</source>
        <translation>ein Punkt liegt außerhalb des CT</translation>
    </message>
    <message>
        <source>point_mm</source>
        <translation>Punkt (mm)</translation>
    </message>
    <message>
        <source>a point lies outside the liver label: place the points inside the lesion, in the liver</source>
        <translation>ein Punkt liegt außerhalb des Leber-Labels: setzen Sie die Punkte in die Läsion, in der Leber</translation>
    </message>
    <message>
        <source>level set: the mask and the contrast image differ in size</source>
        <translation>Level-Set: Maske und Kontrastbild sind verschieden groß</translation>
    </message>
    <message>
        <source>place at least one point inside the organ</source>
        <translation>setzen Sie mindestens einen Punkt in das Organ</translation>
    </message>
    <message>
        <source>the points&apos; intensity window holds nothing: place them inside the organ</source>
        <translation>das Intensitätsfenster der Punkte erfasst nichts: setzen Sie sie in das Organ</translation>
    </message>
    <message>
        <source>no centerlines to measure</source>
        <translation>keine Mittellinien zum Messen</translation>
    </message>
    <message>
        <source>no centerlines to measure: run vascusim-cli centerline first</source>
        <translation>keine Mittellinien zum Messen: führen Sie zuerst vascusim-cli centerline aus</translation>
    </message>
    <message>
        <source>no CT image to segment</source>
        <translation>kein CT-Bild zum Segmentieren</translation>
    </message>
    <message>
        <source>min_contrast_hu must be below max_contrast_hu</source>
        <translation>min_contrast_hu muss unter max_contrast_hu liegen</translation>
    </message>
    <message>
        <source>the segmentation is empty: try a seed inside a vessel or a lower min_contrast_hu</source>
        <translation>die Segmentierung ist leer: versuchen Sie einen Startpunkt im Gefäß oder ein niedrigeres min_contrast_hu</translation>
    </message>
    <message>
        <source>Dice needs two labels on the same grid</source>
        <translation>Dice braucht zwei Labels auf demselben Gitter</translation>
    </message>
    <message>
        <source>the ROI holds no voxel of the image: draw it larger or inside the volume</source>
        <translation>die ROI enthält kein Voxel des Bildes: zeichnen Sie sie größer oder innerhalb des Volumens</translation>
    </message>
    <message>
        <source>an angle&apos;s arms must have a length: its points coincide</source>
        <translation>die Schenkel eines Winkels brauchen eine Länge: seine Punkte fallen zusammen</translation>
    </message>
    <message>
        <source>ITK image is not fully buffered from index 0; cannot adopt it</source>
        <translation>das ITK-Bild ist nicht vollständig ab Index 0 gepuffert; es kann nicht übernommen werden</translation>
    </message>
    <message>
        <source>cannot write NRRD image</source>
        <translation>das NRRD-Bild kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>cannot read NRRD image</source>
        <translation>das NRRD-Bild kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>cannot read NRRD header</source>
        <translation>der NRRD-Header kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>image file is not 3D</source>
        <translation>die Bilddatei ist nicht dreidimensional</translation>
    </message>
    <message>
        <source>VTK image has no scalars</source>
        <translation>das VTK-Bild hat keine Skalare</translation>
    </message>
    <message>
        <source>VTK image scalars are not single-component of the expected type</source>
        <translation>die Skalare des VTK-Bildes sind nicht einkomponentig vom erwarteten Typ</translation>
    </message>
    <message>
        <source>vtk type</source>
        <translation>VTK-Typ</translation>
    </message>
    <message>
        <source>no surface to convert</source>
        <translation>keine Oberfläche zum Umwandeln</translation>
    </message>
    <message>
        <source>surface polygon is not a triangle</source>
        <translation>ein Oberflächenpolygon ist kein Dreieck</translation>
    </message>
    <message>
        <source>points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>no tetrahedral mesh to convert</source>
        <translation>kein Tetraedernetz zum Umwandeln</translation>
    </message>
    <message>
        <source>mesh cell is not a linear tetrahedron</source>
        <translation>eine Netzzelle ist kein linearer Tetraeder</translation>
    </message>
    <message>
        <source>cell</source>
        <translation>Zelle</translation>
    </message>
    <message>
        <source>vtk cell type</source>
        <translation>VTK-Zelltyp</translation>
    </message>
    <message>
        <source>no vessel network to convert</source>
        <translation>kein Gefäßnetz zum Umwandeln</translation>
    </message>
    <message>
        <source>not a vessel network frame: a line does not run from node to node</source>
        <translation>kein Frame eines Gefäßnetzes: eine Linie verläuft nicht von Knoten zu Knoten</translation>
    </message>
    <message>
        <source>line</source>
        <translation>Linie</translation>
    </message>
    <message>
        <source>a grid field does not match its grid</source>
        <translation>ein Gitterfeld passt nicht zu seinem Gitter</translation>
    </message>
    <message>
        <source>not a voxel-grid frame: no point arrays</source>
        <translation>kein Frame eines Voxelgitters: keine Punkt-Arrays</translation>
    </message>
    <message>
        <source>not a voxel-grid frame: a point array is not one value per voxel</source>
        <translation>kein Frame eines Voxelgitters: ein Punkt-Array hat nicht einen Wert je Voxel</translation>
    </message>
    <message>
        <source>not a particle frame: it has lines or polygons</source>
        <translation>kein Partikel-Frame: er hat Linien oder Polygone</translation>
    </message>
    <message>
        <source>particle seeding needs a positive spacing and 1 to 8 wall layers</source>
        <translation>das Setzen der Partikel braucht einen positiven Abstand und 1 bis 8 Wandschichten</translation>
    </message>
    <message>
        <source>an open end needs a unit normal, a positive radius and a positive buffer depth</source>
        <translation>ein offenes Ende braucht eine Einheitsnormale, einen positiven Radius und eine positive Puffertiefe</translation>
    </message>
    <message>
        <source>a vertex budget needs a positive area and vertex count</source>
        <translation>ein Eckpunktbudget braucht eine positive Fläche und Eckpunktzahl</translation>
    </message>
    <message>
        <source>vessel sizing needs centerlines with points</source>
        <translation>die Gefäßgrößen brauchen Mittellinien mit Punkten</translation>
    </message>
    <message>
        <source>the surface to remesh is empty</source>
        <translation>die neu zu vernetzende Oberfläche ist leer</translation>
    </message>
    <message>
        <source>cannot write STL file</source>
        <translation>die STL-Datei kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>array</source>
        <translation>Array</translation>
    </message>
    <message>
        <source>no boundary face of the mesh faces the lumen point; give a point inside the vessel&apos;s lumen</source>
        <translation>keine Randfläche des Netzes ist dem Lumenpunkt zugewandt; geben Sie einen Punkt im Lumen des Gefäßes an</translation>
    </message>
    <message>
        <source>say where the blood pressure acts: --pressure-array NAME (point data, nonzero on the lumen surface) or --lumen-point x,y,z (a point inside the lumen, mm)</source>
        <translation>sagen Sie, wo der Blutdruck wirkt: --pressure-array NAME (Punktdaten, ungleich null auf der Lumenoberfläche) oder --lumen-point x,y,z (ein Punkt im Lumen, mm)</translation>
    </message>
    <message>
        <source>say which nodes are held: --fixed-array NAME (point data, nonzero on held nodes) or --fix-open-ends (the end cuts at the lumen surface&apos;s open ends)</source>
        <translation>sagen Sie, welche Knoten gehalten werden: --fixed-array NAME (Punktdaten, ungleich null an gehaltenen Knoten) oder --fix-open-ends (die Endschnitte an den offenen Enden der Lumenoberfläche)</translation>
    </message>
    <message>
        <source>no boundary face is selected for the pressure: the wall would carry no load</source>
        <translation>keine Randfläche ist für den Druck gewählt: die Wand trüge keine Last</translation>
    </message>
    <message>
        <source>the pressure would act on the whole boundary (inner, outer and end faces): the lumen surface is not parted from the rest by sharp edges; give --pressure-array</source>
        <translation>der Druck wirkte auf den ganzen Rand (Innen-, Außen- und Endflächen): die Lumenoberfläche ist nicht durch scharfe Kanten vom Rest getrennt; geben Sie --pressure-array an</translation>
    </message>
    <message>
        <source>the pressure surface is closed (no open ends): give the held nodes with --fixed-array</source>
        <translation>die Druckfläche ist geschlossen (keine offenen Enden): geben Sie die gehaltenen Knoten mit --fixed-array an</translation>
    </message>
    <message>
        <source>no node is held: the wall would float free</source>
        <translation>kein Knoten wird gehalten: die Wand schwebte frei</translation>
    </message>
    <message>
        <source>the lumen surface is empty: extract the surface first</source>
        <translation>die Lumenoberfläche ist leer: extrahieren Sie zuerst die Oberfläche</translation>
    </message>
    <message>
        <source>a lumen vertex has no normal (degenerate surface)</source>
        <translation>ein Lumen-Eckpunkt hat keine Normale (entartete Oberfläche)</translation>
    </message>
    <message>
        <source>the tetrahedral mesh is not a vessel wall (no wall_layer field)</source>
        <translation>das Tetraedernetz ist keine Gefäßwand (kein Feld wall_layer)</translation>
    </message>
    <message>
        <source>no PDF to encapsulate</source>
        <translation>kein PDF zum Einkapseln</translation>
    </message>
    <message>
        <source>cannot set the encapsulated document&apos;s length</source>
        <translation>die Länge des eingekapselten Dokuments kann nicht gesetzt werden</translation>
    </message>
    <message>
        <source>cannot write the file</source>
        <translation>die Datei kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>the PDF could not be rendered (no fonts or no QGuiApplication)</source>
        <translation>das PDF ließ sich nicht erzeugen (keine Schriften oder keine QGuiApplication)</translation>
    </message>
    <message>
        <source>cannot write the report</source>
        <translation>der Bericht kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>run control: frame intervals must be &gt;= 0, keep_every and max_steps &gt;= 1</source>
        <translation>Laufsteuerung: Frame-Intervalle müssen &gt;= 0 sein, keep_every und max_steps &gt;= 1</translation>
    </message>
    <message>
        <source>multigrid: the matrix, positions and constraints differ in size</source>
        <translation>Mehrgitter: Matrix, Positionen und Zwangsbedingungen sind verschieden groß</translation>
    </message>
    <message>
        <source>multigrid: the coarsest level is not positive definite</source>
        <translation>Mehrgitter: die gröbste Stufe ist nicht positiv definit</translation>
    </message>
    <message>
        <source>the time step must be positive and the Rayleigh coefficients non-negative</source>
        <translation>der Zeitschritt muss positiv sein und die Rayleigh-Koeffizienten nicht negativ</translation>
    </message>
    <message>
        <source>the external forces do not match the mesh</source>
        <translation>die äußeren Kräfte passen nicht zum Netz</translation>
    </message>
    <message>
        <source>conjugate gradients: the matrix, right-hand side, guess and constraints differ in size</source>
        <translation>konjugierte Gradienten: Matrix, rechte Seite, Startwert und Zwangsbedingungen sind verschieden groß</translation>
    </message>
    <message>
        <source>the mesh has no elements</source>
        <translation>das Netz hat keine Elemente</translation>
    </message>
    <message>
        <source>the matrix does not have this mesh&apos;s pattern</source>
        <translation>die Matrix hat nicht das Besetzungsmuster dieses Netzes</translation>
    </message>
    <message>
        <source>this wall has an intraluminal thrombus layer, which the linear wall model (wall_model 0) cannot tell from the wall: run wall_model 1, or build the wall without --thrombus</source>
        <translation>diese Wand hat eine intraluminale Thrombusschicht, die das lineare Wandmodell (wall_model 0) nicht von der Wand unterscheiden kann: rechnen Sie wall_model 1, oder bauen Sie die Wand ohne --thrombus</translation>
    </message>
    <message>
        <source>the physiological protocol needs centerlines (for the local diameter)</source>
        <translation>das physiologische Protokoll braucht Mittellinien (für den lokalen Durchmesser)</translation>
    </message>
    <message>
        <source>equilibrium_tolerance 0 (the damped path&apos;s last state) needs wall_model 0</source>
        <translation>equilibrium_tolerance 0 (der letzte Zustand des gedämpften Pfads) braucht wall_model 0</translation>
    </message>
    <message>
        <source>the wall has no element to take its peak stress from</source>
        <translation>die Wand hat kein Element, aus dem sich ihre Spitzenspannung nehmen ließe</translation>
    </message>
    <message>
        <source>GMRES: the matrix, right-hand side and constraints differ in size</source>
        <translation>GMRES: Matrix, rechte Seite und Zwangsbedingungen sind verschieden groß</translation>
    </message>
    <message>
        <source>hyperelastic polynomial material needs c10 + c01 &gt; 0, c20, c02 &gt;= 0 and a bulk modulus &gt; 0</source>
        <translation>das hyperelastische Polynom-Material braucht c10 + c01 &gt; 0, c20, c02 &gt;= 0 und einen Kompressionsmodul &gt; 0</translation>
    </message>
    <message>
        <source>the quadratic wall model needs a material</source>
        <translation>das quadratische Wandmodell braucht ein Material</translation>
    </message>
    <message>
        <source>quasi-static tearing needs a ramp start &lt; end, a positive increment and tear strength, and an onset tolerance in (0, 0.5)</source>
        <translation>quasistatisches Reißen braucht einen Rampenbeginn &lt; Ende, ein positives Inkrement und eine positive Reißfestigkeit sowie eine Einsatztoleranz in (0, 0,5)</translation>
    </message>
    <message>
        <source>the element field does not match the mesh</source>
        <translation>das Elementfeld passt nicht zum Netz</translation>
    </message>
    <message>
        <source>no element of the wall lies in the aneurysm sac: is the sac measured on the image this wall was built from?</source>
        <translation>kein Element der Wand liegt im Aneurysmasack: wurde der Sack auf dem Bild gemessen, aus dem diese Wand gebaut wurde?</translation>
    </message>
    <message>
        <source>no step along the Newton direction keeps every element uninverted</source>
        <translation>kein Schritt entlang der Newton-Richtung lässt alle Elemente unumgestülpt</translation>
    </message>
    <message>
        <source>the static wall analysis needs a positive pressure and at least one load increment</source>
        <translation>die statische Wandanalyse braucht einen positiven Druck und mindestens ein Lastinkrement</translation>
    </message>
    <message>
        <source>a structured mesh needs at least one cell per axis</source>
        <translation>ein strukturiertes Netz braucht mindestens eine Zelle je Achse</translation>
    </message>
    <message>
        <source>a tube wall needs 0 &lt; inner &lt; outer radius, a positive length and at least 3 cells around</source>
        <translation>eine Rohrwand braucht 0 &lt; Innen- &lt; Außenradius, eine positive Länge und mindestens 3 Zellen im Umfang</translation>
    </message>
    <message>
        <source>an annulus sector needs 0 &lt; inner &lt; outer radius, a positive angle and height</source>
        <translation>ein Ringsektor braucht 0 &lt; Innen- &lt; Außenradius, einen positiven Winkel und eine positive Höhe</translation>
    </message>
    <message>
        <source>the tangent stiffness could not be factorised (a part of the wall is not held by the fixed ends, or the load is past the wall&apos;s limit)</source>
        <translation>die Tangentensteifigkeit ließ sich nicht faktorisieren (ein Teil der Wand wird nicht von den festen Enden gehalten, oder die Last liegt jenseits der Grenze der Wand)</translation>
    </message>
    <message>
        <source>tearing would remove every element of the wall</source>
        <translation>das Reißen entfernte jedes Element der Wand</translation>
    </message>
    <message>
        <source>the tetrahedral mesh is not a vessel wall (wall_layer / end_set fields missing): build it with &apos;mesh wall&apos;</source>
        <translation>das Tetraedernetz ist keine Gefäßwand (Felder wall_layer / end_set fehlen): bauen Sie es mit &apos;mesh wall&apos;</translation>
    </message>
    <message>
        <source>the wall has no fixed end (end_set is 0 everywhere): build it from centerlines with ends</source>
        <translation>die Wand hat kein festes Ende (end_set ist überall 0): bauen Sie sie aus Mittellinien mit Enden</translation>
    </message>
    <message>
        <source>no lumen face carries the pressure</source>
        <translation>keine Lumenfläche trägt den Druck</translation>
    </message>
    <message>
        <source>the run has no pressure curve</source>
        <translation>der Lauf hat keine Druckkurve</translation>
    </message>
    <message>
        <source>dragging the wall needs the CPU backend (the GPU stepper has no contact springs)</source>
        <translation>das Ziehen der Wand braucht das CPU-Backend (der GPU-Zeitschritt hat keine Kontaktfedern)</translation>
    </message>
    <message>
        <source>the heat solver takes no input (its cube comes from the parameters)</source>
        <translation>der Wärmelöser nimmt keine Eingabe (sein Würfel kommt aus den Parametern)</translation>
    </message>
    <message>
        <source>the injection rate must be positive</source>
        <translation>die Injektionsrate muss positiv sein</translation>
    </message>
    <message>
        <source>the arterial inflow must be positive</source>
        <translation>der arterielle Zufluss muss positiv sein</translation>
    </message>
    <message>
        <source>the catheter&apos;s radius and the viscosities must be positive</source>
        <translation>der Radius des Katheters und die Viskositäten müssen positiv sein</translation>
    </message>
    <message>
        <source>the filling takes no input: its network comes with the solved run</source>
        <translation>die Füllung nimmt keine Eingabe: ihr Netz kommt mit dem gelösten Lauf</translation>
    </message>
    <message>
        <source>the flow system is singular: the part downstream of the tip has no outlet pressure to refer to</source>
        <translation>das Strömungssystem ist singulär: der Teil stromab der Spitze hat keinen Auslassdruck als Bezug</translation>
    </message>
    <message>
        <source>the injection needs a positive rate or a tip pressure</source>
        <translation>die Injektion braucht eine positive Rate oder einen Spitzendruck</translation>
    </message>
    <message>
        <source>feeder edit: there is no lesion for a feeder to feed</source>
        <translation>Zuführer bearbeiten: es gibt keine Läsion, die ein Zuführer versorgen könnte</translation>
    </message>
    <message>
        <source>the centerlines have no vessel segments: extract them first (vascusim-cli centerline)</source>
        <translation>die Mittellinien haben keine Gefäßsegmente: extrahieren Sie sie zuerst (vascusim-cli centerline)</translation>
    </message>
    <message>
        <source>feeders are edited on a run with a liver label: give the liver (and the tumour) first</source>
        <translation>Zuführer werden an einem Lauf mit Leber-Label bearbeitet: geben Sie zuerst die Leber (und den Tumor) an</translation>
    </message>
    <message>
        <source>a tip pressure drives the injected drug alone (blood_flow=0); with blood flow the injection is a rate</source>
        <translation>ein Spitzendruck treibt nur den injizierten Wirkstoff (blood_flow=0); mit Blutfluss ist die Injektion eine Rate</translation>
    </message>
    <message>
        <source>the tip pressure does not drive any flow into the network (it is at or below the outlets&apos;)</source>
        <translation>der Spitzendruck treibt keinen Fluss ins Netz (er liegt auf oder unter dem der Auslässe)</translation>
    </message>
    <message>
        <source>the tumour&apos;s radius must be positive</source>
        <translation>der Radius des Tumors muss positiv sein</translation>
    </message>
    <message>
        <source>the liver label has no voxel of the liver&apos;s value</source>
        <translation>das Leber-Label hat kein Voxel mit dem Wert der Leber</translation>
    </message>
    <message>
        <source>no end of the vessel tree lies in the liver: there is no territory to share out</source>
        <translation>kein Ende des Gefäßbaums liegt in der Leber: es gibt kein Versorgungsgebiet aufzuteilen</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>phase densities and viscosities must be positive</source>
        <translation>Dichten und Viskositäten der Phasen müssen positiv sein</translation>
    </message>
    <message>
        <source>the working angle needs a tip away from the root: there is no path to see</source>
        <translation>der Arbeitswinkel braucht eine Spitze abseits der Wurzel: es gibt keinen Pfad zu sehen</translation>
    </message>
    <message>
        <source>the endoscope camera is outside the smoke&apos;s domain or inside tissue</source>
        <translation>die Endoskopkamera liegt außerhalb des Rauchgebiets oder im Gewebe</translation>
    </message>
    <message>
        <source>the liver label is empty: the liver-ablation dome needs the liver&apos;s surface</source>
        <translation>das Leber-Label ist leer: die Kuppel der Leberablation braucht die Oberfläche der Leber</translation>
    </message>
    <message>
        <source>the EVH tunnel needs a centerline of 20 mm or more</source>
        <translation>der EVH-Tunnel braucht eine Mittellinie von 20 mm oder mehr</translation>
    </message>
    <message>
        <source>a suction needs a vent or an open face for the gas it takes out to be replaced</source>
        <translation>eine Absaugung braucht eine Belüftung oder eine offene Fläche, damit das abgesaugte Gas ersetzt wird</translation>
    </message>
    <message>
        <source>the suction port has no fluid cell within its radius</source>
        <translation>die Absaugöffnung hat keine Fluidzelle in ihrem Radius</translation>
    </message>
    <message>
        <source>the dam break needs a positive particle spacing</source>
        <translation>der Dammbruch braucht einen positiven Partikelabstand</translation>
    </message>
    <message>
        <source>the dam break needs at least 1000 particles</source>
        <translation>der Dammbruch braucht mindestens 1000 Partikel</translation>
    </message>
    <message>
        <source>sph-fpm: the moment matrix is singular at a particle next to the wall</source>
        <translation>sph-fpm: die Momentenmatrix ist an einem Partikel neben der Wand singulär</translation>
    </message>
    <message>
        <source>sph-fpm: no particle next to the wall was evaluated</source>
        <translation>sph-fpm: kein Partikel neben der Wand wurde ausgewertet</translation>
    </message>
    <message>
        <source>the neighbour grid&apos;s reach must be a positive length</source>
        <translation>die Reichweite des Nachbarschaftsgitters muss eine positive Länge sein</translation>
    </message>
    <message>
        <source>a particle&apos;s position is not finite: the neighbour grid cannot place it</source>
        <translation>die Position eines Partikels ist nicht endlich: das Nachbarschaftsgitter kann es nicht einordnen</translation>
    </message>
    <message>
        <source>the SPH smoothing length must be a positive length</source>
        <translation>die SPH-Glättungslänge muss eine positive Länge sein</translation>
    </message>
    <message>
        <source>the SPH input&apos;s particles need the field &apos;wall&apos; (1 at wall particles, 0 in the fluid)</source>
        <translation>die Partikel der SPH-Eingabe brauchen das Feld &apos;wall&apos; (1 an Wandpartikeln, 0 im Fluid)</translation>
    </message>
    <message>
        <source>the SPH input has no particles</source>
        <translation>die SPH-Eingabe hat keine Partikel</translation>
    </message>
    <message>
        <source>the stenosis figures need one averaged flow per section</source>
        <translation>die Stenosekennzahlen brauchen eine gemittelte Strömung je Querschnitt</translation>
    </message>
    <message>
        <source>a section the stenosis is compared with holds no fluid</source>
        <translation>ein Querschnitt, mit dem die Stenose verglichen wird, enthält kein Fluid</translation>
    </message>
    <message>
        <source>kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>cannot write skeleton</source>
        <translation>das Skelett kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>cannot write the measurement</source>
        <translation>die Messung kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>cannot parse skeleton</source>
        <translation>das Skelett kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>cannot parse the measurement</source>
        <translation>die Messung kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>unknown artifact kind</source>
        <translation>unbekannte Artefaktart</translation>
    </message>
    <message>
        <source>the mask has no labelled voxel</source>
        <translation>die Maske hat kein markiertes Voxel</translation>
    </message>
    <message>
        <source>study.json is not a VascuSim study manifest</source>
        <translation>study.json ist kein Studienmanifest von VascuSim</translation>
    </message>
    <message>
        <source>software_version</source>
        <translation>Softwareversion</translation>
    </message>
    <message>
        <source>study.json is malformed</source>
        <translation>study.json ist fehlerhaft</translation>
    </message>
    <message>
        <source>the mesh file does not exist</source>
        <translation>die Netzdatei existiert nicht</translation>
    </message>
    <message>
        <source>not a VTK XML unstructured grid (.vtu)</source>
        <translation>kein unstrukturiertes VTK-XML-Gitter (.vtu)</translation>
    </message>
    <message>
        <source>the mesh has no tetrahedra</source>
        <translation>das Netz hat keine Tetraeder</translation>
    </message>
    <message>
        <source>a position must be [x, y, z] in mm</source>
        <translation>eine Position muss [x, y, z] in mm sein</translation>
    </message>
    <message>
        <source>not a vascusim network file (&quot;format&quot;: &quot;vascusim-network&quot; is missing)</source>
        <translation>keine Netzdatei von VascuSim (&quot;format&quot;: &quot;vascusim-network&quot; fehlt)</translation>
    </message>
    <message>
        <source>unsupported network file version (this build reads version 1)</source>
        <translation>nicht unterstützte Version der Netzdatei (dieser Build liest Version 1)</translation>
    </message>
    <message>
        <source>network file not found</source>
        <translation>Netzdatei nicht gefunden</translation>
    </message>
    <message>
        <source>cannot write the network file</source>
        <translation>die Netzdatei kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>a run frame of an unknown format</source>
        <translation>ein Frame eines Laufs in unbekanntem Format</translation>
    </message>
    <message>
        <source>not a run this VascuSim reads</source>
        <translation>kein Lauf, den diese Version von VascuSim liest</translation>
    </message>
    <message>
        <source>cannot parse a run&apos;s run.json</source>
        <translation>die run.json eines Laufs kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>a run is written with its frames in memory</source>
        <translation>ein Lauf wird mit seinen Frames im Speicher geschrieben</translation>
    </message>
    <message>
        <source>a run&apos;s run.json lacks an entry</source>
        <translation>der run.json eines Laufs fehlt ein Eintrag</translation>
    </message>
    <message>
        <source>the folder is a study already; open it instead of creating a new one</source>
        <translation>der Ordner ist bereits eine Studie; öffnen Sie ihn, statt eine neue anzulegen</translation>
    </message>
    <message>
        <source>the folder became a study while waiting for its lock; open it instead</source>
        <translation>der Ordner wurde zur Studie, während auf seine Sperre gewartet wurde; öffnen Sie ihn stattdessen</translation>
    </message>
    <message>
        <source>not a VascuSim study: study.json is missing</source>
        <translation>keine Studie von VascuSim: study.json fehlt</translation>
    </message>
    <message>
        <source>cannot add an empty image to the study</source>
        <translation>ein leeres Bild kann der Studie nicht hinzugefügt werden</translation>
    </message>
    <message>
        <source>cannot add an empty label volume to the study</source>
        <translation>ein leeres Label-Volumen kann der Studie nicht hinzugefügt werden</translation>
    </message>
    <message>
        <source>cannot add an empty surface to the study</source>
        <translation>eine leere Oberfläche kann der Studie nicht hinzugefügt werden</translation>
    </message>
    <message>
        <source>cannot add an empty tetrahedral mesh to the study</source>
        <translation>ein leeres Tetraedernetz kann der Studie nicht hinzugefügt werden</translation>
    </message>
    <message>
        <source>cannot add an empty vessel network to the study</source>
        <translation>ein leeres Gefäßnetz kann der Studie nicht hinzugefügt werden</translation>
    </message>
    <message>
        <source>a run added to the study needs its frames</source>
        <translation>ein der Studie hinzugefügter Lauf braucht seine Frames</translation>
    </message>
    <message>
        <source>a report added to the study must be a PDF</source>
        <translation>ein der Studie hinzugefügter Bericht muss ein PDF sein</translation>
    </message>
    <message>
        <source>the study is open read-only; save it under a new name, or reopen it for writing when its writer has finished</source>
        <translation>die Studie ist schreibgeschützt geöffnet; speichern Sie sie unter neuem Namen, oder öffnen Sie sie zum Schreiben erneut, wenn ihr Schreiber fertig ist</translation>
    </message>
    <message>
        <source>study.json was changed by another program since this study was opened; nothing was written. Save under a new name (Save As) to keep this version</source>
        <translation>study.json wurde seit dem Öffnen dieser Studie von einem anderen Programm geändert; nichts wurde geschrieben. Speichern Sie unter neuem Namen (Speichern unter), um diese Version zu behalten</translation>
    </message>
    <message>
        <source>the folder for the new study is not empty; choose a new folder</source>
        <translation>der Ordner für die neue Studie ist nicht leer; wählen Sie einen neuen Ordner</translation>
    </message>
    <message>
        <source>holder</source>
        <translation>Inhaber</translation>
    </message>
    <message>
        <source>host</source>
        <translation>Rechner</translation>
    </message>
    <message>
        <source>not a NIfTI, NRRD or MetaImage volume (or the file cannot be read)</source>
        <translation>kein NIfTI-, NRRD- oder MetaImage-Volumen (oder die Datei ist nicht lesbar)</translation>
    </message>
    <message>
        <source>cannot read the volume</source>
        <translation>das Volumen kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>the volume file is truncated: it holds fewer bytes than its header announces</source>
        <translation>die Volumendatei ist abgeschnitten: sie enthält weniger Bytes, als ihr Header angibt</translation>
    </message>
    <message>
        <source>bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>voxel bytes expected</source>
        <translation>erwartete Voxel-Bytes</translation>
    </message>
    <message>
        <source>volume file does not exist</source>
        <translation>die Volumendatei existiert nicht</translation>
    </message>
    <message>
        <source>cannot read the volume header</source>
        <translation>der Header des Volumens kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>the volume is not 3D</source>
        <translation>das Volumen ist nicht dreidimensional</translation>
    </message>
    <message>
        <source>dimensions</source>
        <translation>Dimensionen</translation>
    </message>
    <message>
        <source>the volume has more than one component per voxel (colour or vector data)</source>
        <translation>das Volumen hat mehr als eine Komponente je Voxel (Farb- oder Vektordaten)</translation>
    </message>
    <message>
        <source>components</source>
        <translation>Komponenten</translation>
    </message>
    <message>
        <source>cannot write VTK XML file</source>
        <translation>die VTK-XML-Datei kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>file does not exist</source>
        <translation>die Datei existiert nicht</translation>
    </message>
    <message>
        <source>cannot read VTK XML file</source>
        <translation>die VTK-XML-Datei kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>field lines need one value (and radius pair) per line</source>
        <translation>Feldlinien brauchen einen Wert (und ein Radiuspaar) je Linie</translation>
    </message>
    <message>
        <source>3D snapshots need a display (set DISPLAY, or run under xvfb-run)</source>
        <translation>3D-Aufnahmen brauchen ein Display (setzen Sie DISPLAY oder starten Sie unter xvfb-run)</translation>
    </message>
    <message>
        <source>a snapshot needs at least 16 x 16 pixels</source>
        <translation>eine Aufnahme braucht mindestens 16 x 16 Pixel</translation>
    </message>
    <message>
        <source>the offscreen snapshot could not be read back</source>
        <translation>die Offscreen-Aufnahme ließ sich nicht zurücklesen</translation>
    </message>
    <message>
        <source>field points need one value per point</source>
        <translation>Feldpunkte brauchen einen Wert je Punkt</translation>
    </message>
    <message>
        <source>unknown backend &apos;%1&apos; (auto, cpu, cuda)</source>
        <translation>unbekanntes Backend &apos;%1&apos; (auto, cpu, cuda)</translation>
    </message>
    <message>
        <source>%1: use --backend cpu or auto</source>
        <translation>%1: verwenden Sie --backend cpu oder auto</translation>
    </message>
    <message>
        <source>this series is already in the study, as %1 (%2): it is not imported twice</source>
        <translation>diese Serie ist bereits in der Studie, als %1 (%2): sie wird nicht zweimal importiert</translation>
    </message>
    <message>
        <source>no series &apos;%1&apos; among the %2 series found (see --list)</source>
        <translation>keine Serie &apos;%1&apos; unter den %2 gefundenen Serien (siehe --list)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not %2 numbers separated by commas</source>
        <translation>&apos;%1&apos; sind nicht %2 durch Kommas getrennte Zahlen</translation>
    </message>
    <message>
        <source>the needle&apos;s bore (%1 mm) needs at least two particles across: a spacing of at most %2 mm</source>
        <translation>die Bohrung der Kanüle (%1 mm) braucht mindestens zwei Partikel im Querschnitt: einen Abstand von höchstens %2 mm</translation>
    </message>
    <message>
        <source>the tumour volume has no voxel of value %1</source>
        <translation>das Tumorvolumen hat kein Voxel mit dem Wert %1</translation>
    </message>
    <message>
        <source>the tumour must be a label or image artifact, not a %1</source>
        <translation>der Tumor muss ein Label- oder Bild-Artefakt sein, kein %1</translation>
    </message>
    <message>
        <source>the %1 must be a label or image artifact, not a %2</source>
        <translation>%1 muss ein Label- oder Bild-Artefakt sein, kein %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a segment number (feeders.csv lists them)</source>
        <translation>%1: &apos;%2&apos; ist keine Segmentnummer (feeders.csv listet sie)</translation>
    </message>
    <message>
        <source>no such segment: the centerlines have segments 0 to %1</source>
        <translation>kein solches Segment: die Mittellinien haben die Segmente 0 bis %1</translation>
    </message>
    <message>
        <source>unknown smoke scenario &apos;%1&apos; (ball-drop, evh, liver-ablation)</source>
        <translation>unbekanntes Rauchszenario &apos;%1&apos; (ball-drop, evh, liver-ablation)</translation>
    </message>
    <message>
        <source>the vessel ends %1 and %2 are not connected</source>
        <translation>die Gefäßenden %1 und %2 sind nicht verbunden</translation>
    </message>
    <message>
        <source>the centerlines &apos;%1&apos; have no lumen label to fill with particles</source>
        <translation>die Mittellinien &apos;%1&apos; haben kein Lumen-Label, das mit Partikeln gefüllt werden könnte</translation>
    </message>
    <message>
        <source>the vessels need at least two open ends (%1&apos;s and an outlet); the centerlines have %2</source>
        <translation>die Gefäße brauchen mindestens zwei offene Enden (das von %1 und einen Auslass); die Mittellinien haben %2</translation>
    </message>
    <message>
        <source>%1&apos;s node %2 is not a vessel end (ends: %3)</source>
        <translation>Knoten %2 von %1 ist kein Gefäßende (Enden: %3)</translation>
    </message>
    <message>
        <source>unknown report section &apos;%1&apos;; sections: aaa, stenosis, chemoembolization, smoke, measurements, runs</source>
        <translation>unbekannter Berichtsabschnitt &apos;%1&apos;; Abschnitte: aaa, stenosis, chemoembolization, smoke, measurements, runs</translation>
    </message>
    <message>
        <source>unknown language &apos;%1&apos;; use en, de, zh_CN or a catalogue file (.qm)</source>
        <translation>unbekannte Sprache &apos;%1&apos;; verwenden Sie en, de, zh_CN oder eine Katalogdatei (.qm)</translation>
    </message>
    <message>
        <source>the %1 catalogue is missing from this build (:/i18n/vascusim_%2.qm)</source>
        <translation>der Katalog %1 fehlt in diesem Build (:/i18n/vascusim_%2.qm)</translation>
    </message>
    <message>
        <source>the frame has no cell field &apos;%1&apos;</source>
        <translation>der Frame hat kein Zellfeld &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown protocol &apos;%1&apos; (thesis-rupture, physiological, interactive)</source>
        <translation>unbekanntes Protokoll &apos;%1&apos; (thesis-rupture, physiological, interactive)</translation>
    </message>
    <message>
        <source>could not write %1</source>
        <translation>%1 konnte nicht geschrieben werden</translation>
    </message>
    <message>
        <source>the outbox folder exists already: %1</source>
        <translation>der Postausgangsordner existiert bereits: %1</translation>
    </message>
    <message>
        <source>could not write the movie frame %1</source>
        <translation>das Filmbild %1 konnte nicht geschrieben werden</translation>
    </message>
    <message>
        <source>CUDA call failed: %1: %2</source>
        <translation>CUDA-Aufruf gescheitert: %1: %2</translation>
    </message>
    <message>
        <source>the CUDA SPH backend takes at most %1 open boundaries; this case has %2</source>
        <translation>das CUDA-SPH-Backend nimmt höchstens %1 offene Ränder; dieser Fall hat %2</translation>
    </message>
    <message>
        <source>the CUDA SPH backend does not carry a tracer yet: inlet &apos;%1&apos; lets one in; run this case on the CPU (--backend cpu)</source>
        <translation>das CUDA-SPH-Backend transportiert noch keinen Tracer: der Einlass &apos;%1&apos; lässt einen ein; rechnen Sie diesen Fall auf der CPU (--backend cpu)</translation>
    </message>
    <message>
        <source>the SPH domain spans too many cells for the GPU grid: %1</source>
        <translation>das SPH-Gebiet umfasst zu viele Zellen für das GPU-Gitter: %1</translation>
    </message>
    <message>
        <source>the study has no artifact &apos;%1&apos;</source>
        <translation>die Studie hat kein Artefakt &apos;%1&apos;</translation>
    </message>
    <message>
        <source>a UID root is digits in components separated by dots, without leading zeros, at most 32 characters (e.g. 1.2.826.0.1.3680043.10.1234), not &apos;%1&apos;</source>
        <translation>eine UID-Wurzel besteht aus Ziffern in durch Punkte getrennten Komponenten, ohne führende Nullen, höchstens 32 Zeichen (z. B. 1.2.826.0.1.3680043.10.1234), nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the values are not CT Hounsfield units: %1%2</source>
        <translation>die Werte sind keine CT-Hounsfield-Einheiten: %1%2</translation>
    </message>
    <message>
        <source>cannot create the output folder: %1 is a file</source>
        <translation>der Ausgabeordner kann nicht angelegt werden: %1 ist eine Datei</translation>
    </message>
    <message>
        <source>the output folder is VascuSim&apos;s %1 folder, not a %2 folder; choose a new or empty folder</source>
        <translation>der Ausgabeordner ist ein %1-Ordner von VascuSim, kein %2-Ordner; wählen Sie einen neuen oder leeren Ordner</translation>
    </message>
    <message>
        <source>cannot create the output folder: %1</source>
        <translation>der Ausgabeordner kann nicht angelegt werden: %1</translation>
    </message>
    <message>
        <source>unknown parameter &apos;%1&apos;</source>
        <translation>unbekannter Parameter &apos;%1&apos;</translation>
    </message>
    <message>
        <source>parameter &apos;%1&apos; is not a finite number</source>
        <translation>Parameter &apos;%1&apos; ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>parameter &apos;%1&apos; = %2 is outside its range %3</source>
        <translation>Parameter &apos;%1&apos; = %2 liegt außerhalb seines Bereichs %3</translation>
    </message>
    <message>
        <source>parameter &apos;%1&apos; must be a whole number, got %2</source>
        <translation>Parameter &apos;%1&apos; muss eine ganze Zahl sein, erhalten: %2</translation>
    </message>
    <message>
        <source>expected key=value, got &apos;%1&apos;</source>
        <translation>erwartet Schlüssel=Wert, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>parameter &apos;%1&apos; needs a number, got &apos;%2&apos;</source>
        <translation>Parameter &apos;%1&apos; braucht eine Zahl, erhalten: &apos;%2&apos;</translation>
    </message>
    <message>
        <source>the particle field %1 has %2 values for %3 particles</source>
        <translation>das Partikelfeld %1 hat %2 Werte für %3 Partikel</translation>
    </message>
    <message>
        <source>the solver needs a %1 as its input &apos;%2&apos;, and none was given</source>
        <translation>der Löser braucht ein %1 als Eingabe &apos;%2&apos;, und keines wurde angegeben</translation>
    </message>
    <message>
        <source>the solver&apos;s input &apos;%1&apos; must be a %2, not a %3</source>
        <translation>die Eingabe &apos;%1&apos; des Lösers muss ein %2 sein, kein %3</translation>
    </message>
    <message>
        <source>node %1 has a position that is not a number</source>
        <translation>Knoten %1 hat eine Position, die keine Zahl ist</translation>
    </message>
    <message>
        <source>%1 refers to a node that does not exist</source>
        <translation>%1 verweist auf einen Knoten, der nicht existiert</translation>
    </message>
    <message>
        <source>%1 starts and ends at node %2</source>
        <translation>%1 beginnt und endet an Knoten %2</translation>
    </message>
    <message>
        <source>%1 has a length that is not positive</source>
        <translation>%1 hat eine nicht positive Länge</translation>
    </message>
    <message>
        <source>%1 has a negative or invalid resistance</source>
        <translation>%1 hat einen negativen oder ungültigen Widerstand</translation>
    </message>
    <message>
        <source>%1 has a radius that is zero or negative (%2, %3 mm)</source>
        <translation>%1 hat einen Radius von null oder darunter (%2, %3 mm)</translation>
    </message>
    <message>
        <source>%1 (nodes %2 - %3) closes a cycle: the network must be a tree</source>
        <translation>%1 (Knoten %2 - %3) schließt einen Kreis: das Netz muss ein Baum sein</translation>
    </message>
    <message>
        <source>an outlet condition names node %1, which does not exist</source>
        <translation>eine Auslassbedingung nennt Knoten %1, der nicht existiert</translation>
    </message>
    <message>
        <source>the outlet at node %1 has a pressure that is not a number</source>
        <translation>der Auslass an Knoten %1 hat einen Druck, der keine Zahl ist</translation>
    </message>
    <message>
        <source>the outlet at node %1 has a negative or invalid resistance</source>
        <translation>der Auslass an Knoten %1 hat einen negativen oder ungültigen Widerstand</translation>
    </message>
    <message>
        <source>the network&apos;s root is node %1, which does not exist</source>
        <translation>die Wurzel des Netzes ist Knoten %1, der nicht existiert</translation>
    </message>
    <message>
        <source>segment field &apos;%1&apos; has %2 values for %3 segments</source>
        <translation>das Segmentfeld &apos;%1&apos; hat %2 Werte für %3 Segmente</translation>
    </message>
    <message>
        <source>unknown measurement kind &apos;%1&apos; (ruler, angle or roi)</source>
        <translation>unbekannte Messart &apos;%1&apos; (ruler, angle oder roi)</translation>
    </message>
    <message>
        <source>the %1 phantom exists in the analytic style only (--style analytic)</source>
        <translation>das Phantom %1 gibt es nur im analytischen Stil (--style analytic)</translation>
    </message>
    <message>
        <source>unknown transfer syntax &apos;%1&apos;; known: explicit-le, implicit-le, jpeg-lossless, jpeg-ls, rle, jpeg-extended</source>
        <translation>unbekannte Transfersyntax &apos;%1&apos;; bekannt: explicit-le, implicit-le, jpeg-lossless, jpeg-ls, rle, jpeg-extended</translation>
    </message>
    <message>
        <source>unsupported pixel layout: %1 bits allocated</source>
        <translation>nicht unterstütztes Pixelformat: %1 Bits Allocated</translation>
    </message>
    <message>
        <source>invalid Number of Frames: %1</source>
        <translation>ungültige Number of Frames: %1</translation>
    </message>
    <message>
        <source>the series needs %1 of memory for %2 x %3 x %4 voxels, but only %5 is available</source>
        <translation>die Serie braucht %1 Speicher für %2 x %3 x %4 Voxel, verfügbar sind nur %5</translation>
    </message>
    <message>
        <source>cannot decode image %1 of the series: %2</source>
        <translation>Bild %1 der Serie kann nicht dekodiert werden: %2</translation>
    </message>
    <message>
        <source>the DICOM SEG has no %1 for every frame: its geometry is unknown</source>
        <translation>das DICOM SEG hat nicht für jeden Frame ein %1: seine Geometrie ist unbekannt</translation>
    </message>
    <message>
        <source>cannot read %1 as DICOM</source>
        <translation>%1 kann nicht als DICOM gelesen werden</translation>
    </message>
    <message>
        <source>%1 is not a DICOM Segmentation object (SOP class %2)</source>
        <translation>%1 ist kein DICOM-Segmentierungsobjekt (SOP-Klasse %2)</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s image description is incomplete or unsupported (rows %1, columns %2, frames %3, %4 bits, type %5)</source>
        <translation>die Bildbeschreibung des DICOM SEG ist unvollständig oder nicht unterstützt (Zeilen %1, Spalten %2, Frames %3, %4 Bits, Typ %5)</translation>
    </message>
    <message>
        <source>frame %1 of the DICOM SEG names no segment (1..255)</source>
        <translation>Frame %1 des DICOM SEG nennt kein Segment (1..255)</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s frames are not a regular stack (positions along the normal are not whole multiples of %1 mm apart)</source>
        <translation>die Frames des DICOM SEG bilden keinen regelmäßigen Stapel (die Positionen entlang der Normalen liegen nicht ganzzahlige Vielfache von %1 mm auseinander)</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s grid is too large (%1 x %2 x %3 voxels)</source>
        <translation>das Gitter des DICOM SEG ist zu groß (%1 x %2 x %3 Voxel)</translation>
    </message>
    <message>
        <source>the DICOM SEG&apos;s pixel data is shorter than its frames (%1 of %2 bytes)</source>
        <translation>die Pixeldaten des DICOM SEG sind kürzer als seine Frames (%1 von %2 Bytes)</translation>
    </message>
    <message>
        <source>writing the DICOM SEG failed at %1: %2</source>
        <translation>das Schreiben des DICOM SEG ist bei %1 gescheitert: %2</translation>
    </message>
    <message>
        <source>writing the DICOM SEG failed at the derivation image of slice %1</source>
        <translation>das Schreiben des DICOM SEG ist am Ableitungsbild der Schicht %1 gescheitert</translation>
    </message>
    <message>
        <source>writing the DICOM SEG failed: segment %1 for label value %2</source>
        <translation>das Schreiben des DICOM SEG ist gescheitert: Segment %1 für den Label-Wert %2</translation>
    </message>
    <message>
        <source>AE titles have 1 to 16 characters (PACS &apos;%1&apos;, ours &apos;%2&apos;)</source>
        <translation>AE-Titel haben 1 bis 16 Zeichen (PACS &apos;%1&apos;, unserer &apos;%2&apos;)</translation>
    </message>
    <message>
        <source>a PACS node needs a host and a port from 1 to 65535 (%1)</source>
        <translation>ein PACS-Knoten braucht einen Host und einen Port von 1 bis 65535 (%1)</translation>
    </message>
    <message>
        <source>the PACS %1 rejected the association: is our AE title &apos;%2&apos; registered there, and is its own &apos;%3&apos;?</source>
        <translation>das PACS %1 hat die Assoziation abgelehnt: ist unser AE-Titel &apos;%2&apos; dort registriert, und ist seiner &apos;%3&apos;?</translation>
    </message>
    <message>
        <source>the PACS %1 took the connection but did not answer within %2 s (is it a DICOM node, is the port its DICOM port, and does it speak DICOM TLS there?)</source>
        <translation>das PACS %1 hat die Verbindung angenommen, aber nicht innerhalb von %2 s geantwortet (ist es ein DICOM-Knoten, ist der Port sein DICOM-Port, und spricht es dort DICOM TLS?)</translation>
    </message>
    <message>
        <source>the PACS %1 took the connection but did not answer within %2 s (is it a DICOM node, and is the port its DICOM port?)</source>
        <translation>das PACS %1 hat die Verbindung angenommen, aber nicht innerhalb von %2 s geantwortet (ist es ein DICOM-Knoten, und ist der Port sein DICOM-Port?)</translation>
    </message>
    <message>
        <source>could not connect over DICOM TLS (%1): %2 (does the PACS speak TLS on this port, is its certificate among those we trust (%3), and does it trust ours?)</source>
        <translation>keine Verbindung über DICOM TLS (%1): %2 (spricht das PACS auf diesem Port TLS, ist sein Zertifikat unter denen, denen wir vertrauen (%3), und vertraut es unserem?)</translation>
    </message>
    <message>
        <source>the PACS %1 does not offer %2</source>
        <translation>das PACS %1 bietet %2 nicht an</translation>
    </message>
    <message>
        <source>%1 (%2): %3</source>
        <translation>%1 (%2): %3</translation>
    </message>
    <message>
        <source>the retrieve&apos;s folder is not empty: %1</source>
        <translation>der Ordner des Abrufs ist nicht leer: %1</translation>
    </message>
    <message>
        <source>cannot create the retrieve&apos;s folder %1: %2</source>
        <translation>der Ordner %1 des Abrufs kann nicht angelegt werden: %2</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>the move&apos;s listening port must be from 1 to 65535, not %1</source>
        <translation>der Empfangsport der Verschiebung muss von 1 bis 65535 sein, nicht %1</translation>
    </message>
    <message>
        <source>cannot listen on port %1 for the move: %2 (is another program using it?)</source>
        <translation>auf Port %1 kann für die Verschiebung nicht gelauscht werden: %2 (verwendet ihn ein anderes Programm?)</translation>
    </message>
    <message>
        <source>not a DICOM file: %1 (%2)</source>
        <translation>keine DICOM-Datei: %1 (%2)</translation>
    </message>
    <message>
        <source>a DICOM object to store needs its SOP class, instance and study UIDs: %1</source>
        <translation>ein zu sendendes DICOM-Objekt braucht seine SOP-Klasse sowie Instance- und Study-UIDs: %1</translation>
    </message>
    <message>
        <source>%1 is de-identified (Patient Identity Removed YES, e.g. a report made with --anonymize): it is not stored into a patient&apos;s study. Nothing was sent; to store it as a new anonymized study, ask for that (pacs store --anonymized new-study)</source>
        <translation>%1 ist de-identifiziert (Patient Identity Removed YES, z. B. ein mit --anonymize erstellter Bericht): es wird nicht in die Studie eines Patienten gesendet. Nichts wurde gesendet; um es als neue anonymisierte Studie zu senden, verlangen Sie das (pacs store --anonymized new-study)</translation>
    </message>
    <message>
        <source>the store of %1 broke off (%2): %3; %4</source>
        <translation>das Senden von %1 brach ab (%2): %3; %4</translation>
    </message>
    <message>
        <source>the PACS %1 refused %2 with status %3; %4</source>
        <translation>das PACS %1 hat %2 mit Status %3 abgelehnt; %4</translation>
    </message>
    <message>
        <source>DICOM TLS: %1: %2</source>
        <translation>DICOM TLS: %1: %2</translation>
    </message>
    <message>
        <source>DICOM TLS needs %1 (a PEM file)</source>
        <translation>DICOM TLS braucht %1 (eine PEM-Datei)</translation>
    </message>
    <message>
        <source>DICOM TLS: %1 is not a file: %2</source>
        <translation>DICOM TLS: %1 ist keine Datei: %2</translation>
    </message>
    <message>
        <source>DICOM TLS: the private key %1 is not that of the certificate %2</source>
        <translation>DICOM TLS: der private Schlüssel %1 gehört nicht zum Zertifikat %2</translation>
    </message>
    <message>
        <source>unknown phantom kind &apos;%1&apos;; known kinds: aaa, stenosis, hepatic-tree, bifurcation</source>
        <translation>unbekannte Phantomart &apos;%1&apos;; bekannt: aaa, stenosis, hepatic-tree, bifurcation</translation>
    </message>
    <message>
        <source>unknown phantom style &apos;%1&apos;; known styles: patient, analytic</source>
        <translation>unbekannter Phantomstil &apos;%1&apos;; bekannt: patient, analytic</translation>
    </message>
    <message>
        <source>the vessel label is disconnected: skeleton nodes %1 and %2 cannot be reached from the root through the lumen; segment one vessel tree from a seed, or join the parts with the brush</source>
        <translation>das Gefäß-Label ist nicht zusammenhängend: die Skelettknoten %1 und %2 sind von der Wurzel aus nicht durch das Lumen erreichbar; segmentieren Sie einen Gefäßbaum von einem Startpunkt aus, oder verbinden Sie die Teile mit dem Pinsel</translation>
    </message>
    <message>
        <source>the centerline is shorter than one step (%1 mm)</source>
        <translation>die Mittellinie ist kürzer als ein Schritt (%1 mm)</translation>
    </message>
    <message>
        <source>the point %1 lies outside the image; pick it on the images</source>
        <translation>der Punkt %1 liegt außerhalb des Bildes; wählen Sie ihn auf den Bildern</translation>
    </message>
    <message>
        <source>no tissue darker than the point %1 around it (%2 HU): is it inside a vessel, and is the image contrast-enhanced CT?</source>
        <translation>kein Gewebe um den Punkt %1 ist dunkler als er (%2 HU): liegt er in einem Gefäß, und ist das Bild ein kontrastverstärktes CT?</translation>
    </message>
    <message>
        <source>the point %1 is not in a contrast-filled vessel (%2 HU against %3 HU around it); pick a point inside the lumen</source>
        <translation>der Punkt %1 liegt in keinem kontrastgefüllten Gefäß (%2 HU gegenüber %3 HU in der Umgebung); wählen Sie einen Punkt im Lumen</translation>
    </message>
    <message>
        <source>unknown segmentation target &apos;%1&apos;; known targets: aorta, hepatic, all</source>
        <translation>unbekanntes Segmentierungsziel &apos;%1&apos;; bekannt: aorta, hepatic, all</translation>
    </message>
    <message>
        <source>the intensities are not CT Hounsfield units (%1): import the CT rescaled to HU (vascusim-cli import --rescale SLOPE,INTERCEPT), not MR</source>
        <translation>die Intensitäten sind keine CT-Hounsfield-Einheiten (%1): importieren Sie das CT auf HU skaliert (vascusim-cli import --rescale SLOPE,INTERCEPT), kein MR</translation>
    </message>
    <message>
        <source>the points&apos; tissue (%1 HU) lies within the liver&apos;s own range (%2 +/- %3 HU): place them in the lesion&apos;s darker (or brighter) part, or lower lesion_sigmas</source>
        <translation>das Gewebe der Punkte (%1 HU) liegt im eigenen Bereich der Leber (%2 +/- %3 HU): setzen Sie sie in den dunkleren (oder helleren) Teil der Läsion, oder senken Sie lesion_sigmas</translation>
    </message>
    <message>
        <source>the seed (%1, %2, %3) mm lies outside the image: click inside a vessel</source>
        <translation>der Startpunkt (%1, %2, %3) mm liegt außerhalb des Bildes: klicken Sie in ein Gefäß</translation>
    </message>
    <message>
        <source>the seed is not in a contrast-filled vessel: %1 HU there, outside %2..%3 HU; click inside a bright vessel or change min_contrast_hu / max_contrast_hu</source>
        <translation>der Startpunkt liegt in keinem kontrastgefüllten Gefäß: dort %1 HU, außerhalb von %2..%3 HU; klicken Sie in ein helles Gefäß oder ändern Sie min_contrast_hu / max_contrast_hu</translation>
    </message>
    <message>
        <source>no contrast-filled vessel found (no thick region of %1..%2 HU): is this a contrast-enhanced CTA? Give a seed inside a vessel or lower min_contrast_hu</source>
        <translation>kein kontrastgefülltes Gefäß gefunden (kein dicker Bereich von %1..%2 HU): ist dies eine kontrastverstärkte CTA? Geben Sie einen Startpunkt in einem Gefäß an oder senken Sie min_contrast_hu</translation>
    </message>
    <message>
        <source>the seed lies where the smoothed image is below the vessel boundary (%1 HU): click nearer the centre of the vessel</source>
        <translation>der Startpunkt liegt dort, wo das geglättete Bild unter der Gefäßgrenze (%1 HU) liegt: klicken Sie näher an die Gefäßmitte</translation>
    </message>
    <message>
        <source>a %1 takes %2 points</source>
        <translation>ein %1 braucht %2 Punkte</translation>
    </message>
    <message>
        <source>not a vessel network frame: the array %1 is missing</source>
        <translation>kein Frame eines Gefäßnetzes: das Array %1 fehlt</translation>
    </message>
    <message>
        <source>the label has no lumen voxels (value %1) to fill with particles</source>
        <translation>das Label hat keine Lumen-Voxel (Wert %1), die mit Partikeln gefüllt werden könnten</translation>
    </message>
    <message>
        <source>a particle spacing of %1 mm needs %2 lattice points over the lumen: choose a larger spacing</source>
        <translation>ein Partikelabstand von %1 mm braucht %2 Gitterpunkte über dem Lumen: wählen Sie einen größeren Abstand</translation>
    </message>
    <message>
        <source>the mesh has no point-data array &apos;%1&apos; for %2 (its arrays: %3)</source>
        <translation>das Netz hat kein Punktdaten-Array &apos;%1&apos; für %2 (seine Arrays: %3)</translation>
    </message>
    <message>
        <source>the vessel end %1 cuts no triangle of the lumen surface: is the surface from the same label as the centerlines?</source>
        <translation>das Gefäßende %1 schneidet kein Dreieck der Lumenoberfläche: stammt die Oberfläche aus demselben Label wie die Mittellinien?</translation>
    </message>
    <message>
        <source>the wall thickness must lie in 0.1..10 mm (%1 given)</source>
        <translation>die Wanddicke muss in 0,1..10 mm liegen (%1 angegeben)</translation>
    </message>
    <message>
        <source>cannot set a DICOM attribute of the report: %1</source>
        <translation>ein DICOM-Attribut des Berichts kann nicht gesetzt werden: %1</translation>
    </message>
    <message>
        <source>cannot encapsulate the PDF: %1</source>
        <translation>das PDF kann nicht eingekapselt werden: %1</translation>
    </message>
    <message>
        <source>cannot write the DICOM report: %1</source>
        <translation>der DICOM-Bericht kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>unknown page size &apos;%1&apos;; use a4 or letter</source>
        <translation>unbekanntes Papierformat &apos;%1&apos;; verwenden Sie a4 oder letter</translation>
    </message>
    <message>
        <source>%1: the initial state holds %2</source>
        <translation>%1: der Anfangszustand enthält %2</translation>
    </message>
    <message>
        <source>a spring constraint names node %1 of %2</source>
        <translation>eine Federbedingung nennt Knoten %1 von %2</translation>
    </message>
    <message>
        <source>element %1 refers to node %2 of %3</source>
        <translation>Element %1 verweist auf Knoten %2 von %3</translation>
    </message>
    <message>
        <source>element %1: %2</source>
        <translation>Element %1: %2</translation>
    </message>
    <message>
        <source>Young&apos;s modulus must be positive (%1 Pa given)</source>
        <translation>der Elastizitätsmodul muss positiv sein (%1 Pa angegeben)</translation>
    </message>
    <message>
        <source>Poisson&apos;s ratio must lie in (-1, 0.5) (%1 given)</source>
        <translation>die Querkontraktionszahl muss in (-1, 0,5) liegen (%1 angegeben)</translation>
    </message>
    <message>
        <source>the density must be positive (%1 kg/m^3 given)</source>
        <translation>die Dichte muss positiv sein (%1 kg/m^3 angegeben)</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos; (known: %2)</source>
        <translation>unbekannter Validierungsfall &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <source>St. Venant-Kirchhoff material needs mu &gt; 0 and lambda &gt;= 0 (got mu %1 Pa, lambda %2 Pa)</source>
        <translation>das St.-Venant-Kirchhoff-Material braucht mu &gt; 0 und lambda &gt;= 0 (erhalten: mu %1 Pa, lambda %2 Pa)</translation>
    </message>
    <message>
        <source>the quadratic wall model has %1 material indices for %2 elements</source>
        <translation>das quadratische Wandmodell hat %1 Materialindizes für %2 Elemente</translation>
    </message>
    <message>
        <source>element %1 has material %2 of %3</source>
        <translation>Element %1 hat Material %2 von %3</translation>
    </message>
    <message>
        <source>quadratic element %1 is degenerate or inverted (volume %2 m^3)</source>
        <translation>das quadratische Element %1 ist entartet oder umgestülpt (Volumen %2 m^3)</translation>
    </message>
    <message>
        <source>%1 elements are inverted at the start of the static solve%2</source>
        <translation>%1 Elemente sind zu Beginn der statischen Lösung umgestülpt%2</translation>
    </message>
    <message>
        <source>the saved wall state has %1 nodes, the wall %2</source>
        <translation>der gespeicherte Wandzustand hat %1 Knoten, die Wand %2</translation>
    </message>
    <message>
        <source>heat-decay: the run at %1 cells stopped: %2</source>
        <translation>heat-decay: der Lauf mit %1 Zellen hielt an: %2</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos; (known: heat-decay)</source>
        <translation>unbekannter Validierungsfall &apos;%1&apos; (bekannt: heat-decay)</translation>
    </message>
    <message>
        <source>outlet node %1 has no boundary condition (a pressure or a terminal resistance)</source>
        <translation>der Auslassknoten %1 hat keine Randbedingung (einen Druck oder einen Endwiderstand)</translation>
    </message>
    <message>
        <source>node %1 takes in flow but no open vessel leaves it</source>
        <translation>Knoten %1 nimmt Fluss auf, aber kein offenes Gefäß verlässt ihn</translation>
    </message>
    <message>
        <source>the inlet segment %1 does not exist (the tree has %2 segments)</source>
        <translation>das Einlasssegment %1 existiert nicht (der Baum hat %2 Segmente)</translation>
    </message>
    <message>
        <source>the inlet &apos;%1&apos; is not a point x,y,z (mm)</source>
        <translation>der Einlass &apos;%1&apos; ist kein Punkt x,y,z (mm)</translation>
    </message>
    <message>
        <source>the inlet point %1 lies %2 mm from the nearest vessel (at most %3 mm)</source>
        <translation>der Einlasspunkt %1 liegt %2 mm vom nächsten Gefäß entfernt (höchstens %3 mm)</translation>
    </message>
    <message>
        <source>no segment of the tree is named &apos;%1&apos;%2</source>
        <translation>kein Segment des Baums heißt &apos;%1&apos;%2</translation>
    </message>
    <message>
        <source>feeder edit: segment %1 is not in the network (%2 segments)</source>
        <translation>Zuführer bearbeiten: Segment %1 ist nicht im Netz (%2 Segmente)</translation>
    </message>
    <message>
        <source>feeder edit: segment %1 is both added and removed</source>
        <translation>Zuführer bearbeiten: Segment %1 wird zugleich hinzugefügt und entfernt</translation>
    </message>
    <message>
        <source>end radii are given for %1 of %2 centerline edges</source>
        <translation>Endradien sind für %1 von %2 Mittellinienkanten angegeben</translation>
    </message>
    <message>
        <source>centerline edge %1 has no positive radius: measure the vessels again</source>
        <translation>die Mittellinienkante %1 hat keinen positiven Radius: messen Sie die Gefäße erneut</translation>
    </message>
    <message>
        <source>control point %1 is not on the tree downstream of the tip</source>
        <translation>der Kontrollpunkt %1 liegt nicht stromab der Spitze auf dem Baum</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos;; network cases: network-cylinder, network-cone, network-conservation, network-bifurcation, network-confluence, network-annulus, network-mixing, network-two-phase-split</source>
        <translation>unbekannter Validierungsfall &apos;%1&apos;; Netzfälle: network-cylinder, network-cone, network-conservation, network-bifurcation, network-confluence, network-annulus, network-mixing, network-two-phase-split</translation>
    </message>
    <message>
        <source>the catheter tip is node %1, which is not in the network</source>
        <translation>die Katheterspitze ist Knoten %1, der nicht im Netz ist</translation>
    </message>
    <message>
        <source>the catheter tip (node %1) is on a part of the network that is not connected to its root</source>
        <translation>die Katheterspitze (Knoten %1) liegt auf einem Teil des Netzes, der nicht mit seiner Wurzel verbunden ist</translation>
    </message>
    <message>
        <source>nothing is downstream of the catheter tip (node %1 is an end of the tree): place it nearer the root (node %2)</source>
        <translation>stromab der Katheterspitze liegt nichts (Knoten %1 ist ein Ende des Baums): setzen Sie sie näher an die Wurzel (Knoten %2)</translation>
    </message>
    <message>
        <source>the void fraction must be in [0, 1), not %1</source>
        <translation>der Hohlraumanteil muss in [0, 1) liegen, nicht %1</translation>
    </message>
    <message>
        <source>the catheter tip (node %1) is not connected to the root</source>
        <translation>die Katheterspitze (Knoten %1) ist nicht mit der Wurzel verbunden</translation>
    </message>
    <message>
        <source>a smoke grid needs at least 2 cells along each axis and a positive cell size (got %1 x %2 x %3)</source>
        <translation>ein Rauchgitter braucht mindestens 2 Zellen je Achse und eine positive Zellgröße (erhalten: %1 x %2 x %3)</translation>
    </message>
    <message>
        <source>smoke-taylor-green: %1</source>
        <translation>smoke-taylor-green: %1</translation>
    </message>
    <message>
        <source>smoke-mass: %1</source>
        <translation>smoke-mass: %1</translation>
    </message>
    <message>
        <source>smoke-ball: %1</source>
        <translation>smoke-ball: %1</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos; (known: smoke-divergence, smoke-taylor-green, smoke-mass, smoke-ball)</source>
        <translation>unbekannter Validierungsfall &apos;%1&apos; (bekannt: smoke-divergence, smoke-taylor-green, smoke-mass, smoke-ball)</translation>
    </message>
    <message>
        <source>%1: the run stopped: %2</source>
        <translation>%1: der Lauf hielt an: %2</translation>
    </message>
    <message>
        <source>a periodic axis must be at least 2.5 kernel supports long (%1 mm)</source>
        <translation>eine periodische Achse muss mindestens 2,5 Kernträger lang sein (%1 mm)</translation>
    </message>
    <message>
        <source>the particles spread over more than %1 neighbour cells</source>
        <translation>die Partikel verteilen sich über mehr als %1 Nachbarzellen</translation>
    </message>
    <message>
        <source>the open boundary &apos;%1&apos; needs a unit normal and a positive radius</source>
        <translation>der offene Rand &apos;%1&apos; braucht eine Einheitsnormale und einen positiven Radius</translation>
    </message>
    <message>
        <source>a buffer particle names open boundary %1 of %2</source>
        <translation>ein Pufferpartikel nennt den offenen Rand %1 von %2</translation>
    </message>
    <message>
        <source>the open boundary &apos;%1&apos; has no buffer particles behind it</source>
        <translation>der offene Rand &apos;%1&apos; hat keine Pufferpartikel hinter sich</translation>
    </message>
    <message>
        <source>unknown validation case &apos;%1&apos; (known: sph-kernel, sph-fpm, sph-hydrostatic, sph-poiseuille, sph-womersley, sph-mass, sph-stenosis)</source>
        <translation>unbekannter Validierungsfall &apos;%1&apos; (bekannt: sph-kernel, sph-fpm, sph-hydrostatic, sph-poiseuille, sph-womersley, sph-mass, sph-stenosis)</translation>
    </message>
    <message>
        <source>the stenosis pipe needs a mean speed &gt; 0 and room for the sections past the throat (length &gt;= %1 mm)</source>
        <translation>das Stenoserohr braucht eine mittlere Geschwindigkeit &gt; 0 und Platz für die Querschnitte hinter der Engstelle (Länge &gt;= %1 mm)</translation>
    </message>
    <message>
        <source>no section lies %1 mm from both ends of the path to compare with</source>
        <translation>kein Querschnitt liegt %1 mm von beiden Enden des Pfads entfernt, mit dem verglichen werden könnte</translation>
    </message>
    <message>
        <source>unknown artifact kind &apos;%1&apos;</source>
        <translation>unbekannte Artefaktart &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>cannot replace file: %1</source>
        <translation>die Datei kann nicht ersetzt werden: %1</translation>
    </message>
    <message>
        <source>the mask&apos;s grid does not match the image&apos;s (%1): mask %2; image %3</source>
        <translation>das Gitter der Maske passt nicht zu dem des Bildes (%1): Maske %2; Bild %3</translation>
    </message>
    <message>
        <source>the mask holds the value %1, outside the labels 1..255: give the label value to use (--label-value N)</source>
        <translation>die Maske enthält den Wert %1, außerhalb der Labels 1..255: geben Sie den zu verwendenden Label-Wert an (--label-value N)</translation>
    </message>
    <message>
        <source>the study was written by a newer VascuSim (schema %1); this build reads schema %2 and older</source>
        <translation>die Studie wurde von einer neueren Version von VascuSim geschrieben (Schema %1); dieser Build liest Schema %2 und älter</translation>
    </message>
    <message>
        <source>segment %1 of the network file: %2</source>
        <translation>Segment %1 der Netzdatei: %2</translation>
    </message>
    <message>
        <source>cannot read the network file: %1</source>
        <translation>die Netzdatei kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>the run has no frame %1 (it kept %2)</source>
        <translation>der Lauf hat keinen Frame %1 (er hat %2 behalten)</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; is a %2, not a %3</source>
        <translation>das Artefakt &apos;%1&apos; ist ein %2, kein %3</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; is damaged: %2</source>
        <translation>das Artefakt &apos;%1&apos; ist beschädigt: %2</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; is a %2, not a run</source>
        <translation>das Artefakt &apos;%1&apos; ist ein %2, kein Lauf</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; is not a volume</source>
        <translation>das Artefakt &apos;%1&apos; ist kein Volumen</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; was not removed; nothing to restore</source>
        <translation>das Artefakt &apos;%1&apos; wurde nicht entfernt; nichts wiederherzustellen</translation>
    </message>
    <message>
        <source>cannot open the study&apos;s lock file: %1</source>
        <translation>die Sperrdatei der Studie kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>cannot lock the study: %1</source>
        <translation>die Studie kann nicht gesperrt werden: %1</translation>
    </message>
    <message>
        <source>the study is being written by %1; wait for it (--wait SECONDS) or open the study read-only</source>
        <translation>die Studie wird gerade von %1 geschrieben; warten Sie darauf (--wait SEKUNDEN) oder öffnen Sie die Studie schreibgeschützt</translation>
    </message>
    <message>
        <source>cannot move the stale lock aside: %1</source>
        <translation>die verwaiste Sperre kann nicht beiseitegelegt werden: %1</translation>
    </message>
    <message>
        <source>the surface has no field &apos;%1&apos; to colour by</source>
        <translation>die Oberfläche hat kein Feld &apos;%1&apos; zum Einfärben</translation>
    </message>
    <message>
        <source>the %1 frame has no field &apos;%2&apos; to show in the slices</source>
        <translation>der Frame %1 hat kein Feld &apos;%2&apos;, das in den Schichten gezeigt werden könnte</translation>
    </message>
    <message>
        <source>an element is inverted at rest (negative volume)</source>
        <translation>ein Element ist in Ruhe umgestülpt (negatives Volumen)</translation>
    </message>
    <message>
        <source>an element is degenerate at rest (flat or zero volume)</source>
        <translation>ein Element ist in Ruhe entartet (flach oder Volumen null)</translation>
    </message>
    <message>
        <source>a tumour grown in its own window holds its darkest part only: give the liver label with --within for the lesion&apos;s boundary against the parenchyma</source>
        <translation>ein in eigenem Fenster gewachsener Tumor enthält nur seinen dunkelsten Teil: geben Sie das Leberlabel mit --within an, um die Grenze der Läsion zum Parenchym zu finden</translation>
    </message>
    <message>
        <source>the run ends before the inflow has risen (%1 s): the figures are not of a settled flow</source>
        <translation>der Lauf endet, bevor der Zufluss angestiegen ist (%1 s): die Kennzahlen stammen nicht von einer eingeschwungenen Strömung</translation>
    </message>
    <message>
        <source>the averaging starts %1 s after the inflow&apos;s rise, under three settling times (3 x %2 s: the vessel&apos;s resistance x compliance at this sound speed): the figures may not be of a settled flow</source>
        <translation>die Mittelung beginnt %1 s nach dem Anstieg des Zuflusses, unter drei Einschwingzeiten (3 x %2 s: Widerstand x Compliance des Gefäßes bei dieser Schallgeschwindigkeit): die Kennzahlen stammen womöglich nicht von einer eingeschwungenen Strömung</translation>
    </message>
    <message>
        <source>no stenosis figures: %1</source>
        <translation>keine Stenosekennzahlen: %1</translation>
    </message>
    <message>
        <source>the run stopped before its averaging window (from %1 s): no section averages or stenosis figures</source>
        <translation>der Lauf endete vor seinem Mittelungsfenster (ab %1 s): keine Querschnittsmittel oder Stenosekennzahlen</translation>
    </message>
    <message>
        <source>no liver label in the study (vascusim-cli segment-organ --organ liver): the box phantom was used</source>
        <translation>kein Leberlabel in der Studie (vascusim-cli segment-organ --organ liver): das Quader-Phantom wurde verwendet</translation>
    </message>
    <message>
        <source>ran on the CPU: %1</source>
        <translation>lief auf der CPU: %1</translation>
    </message>
    <message>
        <source>stopped early: %1</source>
        <translation>vorzeitig beendet: %1</translation>
    </message>
    <message>
        <source>the open boundaries let in more particles than the GPU&apos;s arrays hold (%1)</source>
        <translation>die offenen Ränder ließen mehr Teilchen ein, als die Felder der GPU fassen (%1)</translation>
    </message>
    <message>
        <source>at t = %1 s %2</source>
        <translation>bei t = %1 s: %2</translation>
    </message>
    <message>
        <source>particle %1 has a value that is not finite</source>
        <translation>Teilchen %1 hat einen nicht endlichen Wert</translation>
    </message>
    <message>
        <source>particle %1 left the domain (through a wall or an open end without an outlet)</source>
        <translation>Teilchen %1 hat das Gebiet verlassen (durch eine Wand oder ein offenes Ende ohne Auslass)</translation>
    </message>
    <message>
        <source>values rescaled to HU by the user&apos;s rescale: HU = %1 x stored + %2</source>
        <translation>Werte mit der Umrechnung des Benutzers in HU umgerechnet: HU = %1 x gespeichert + %2</translation>
    </message>
    <message>
        <source>%1 voxels clamped to the int16 range</source>
        <translation>%1 Voxel auf den int16-Bereich begrenzt</translation>
    </message>
    <message>
        <source>modality is %1, not CT: values are not Hounsfield units</source>
        <translation>Modalität ist %1, nicht CT: die Werte sind keine Hounsfield-Einheiten</translation>
    </message>
    <message>
        <source>%1 values outside -32768..32767 HU were clamped</source>
        <translation>%1 Werte außerhalb von -32768..32767 HU wurden begrenzt</translation>
    </message>
    <message>
        <source>modality is missing, not CT: values are not Hounsfield units</source>
        <translation>Modalität fehlt, nicht CT: die Werte sind keine Hounsfield-Einheiten</translation>
    </message>
    <message>
        <source>%1 localizer image skipped</source>
        <translation>%1 Übersichtsaufnahme übersprungen</translation>
    </message>
    <message>
        <source>%1 localizer images skipped</source>
        <translation>%1 Übersichtsaufnahmen übersprungen</translation>
    </message>
    <message>
        <source>series split into %1 sub-series (orientation, image size, pixel spacing, image type or acquisition differ); this is part %2</source>
        <translation>Serie in %1 Teilserien aufgeteilt (Orientierung, Bildgröße, Pixelabstand, Bildtyp oder Akquisition unterscheiden sich); dies ist Teil %2</translation>
    </message>
    <message>
        <source>%1 file is not DICOM (skipped)</source>
        <translation>%1 Datei ist kein DICOM (übersprungen)</translation>
    </message>
    <message>
        <source>%1 files are not DICOM (skipped)</source>
        <translation>%1 Dateien sind kein DICOM (übersprungen)</translation>
    </message>
    <message>
        <source>%1 DICOM file holds no image (DICOMDIR, reports, ...; skipped)</source>
        <translation>%1 DICOM-Datei enthält kein Bild (DICOMDIR, Befunde, ...; übersprungen)</translation>
    </message>
    <message>
        <source>%1 DICOM files hold no image (DICOMDIR, reports, ...; skipped)</source>
        <translation>%1 DICOM-Dateien enthalten kein Bild (DICOMDIR, Befunde, ...; übersprungen)</translation>
    </message>
    <message>
        <source>%1 DICOM file is damaged or truncated (skipped)</source>
        <translation>%1 DICOM-Datei ist beschädigt oder abgeschnitten (übersprungen)</translation>
    </message>
    <message>
        <source>%1 DICOM files are damaged or truncated (skipped)</source>
        <translation>%1 DICOM-Dateien sind beschädigt oder abgeschnitten (übersprungen)</translation>
    </message>
    <message>
        <source>%1 voxels belong to several segments: the higher segment number is kept</source>
        <translation>%1 Voxel gehören zu mehreren Segmenten: die höhere Segmentnummer wird behalten</translation>
    </message>
    <message>
        <source>%1 slices at duplicate positions dropped (kept the lowest instance number)</source>
        <translation>%1 Schichten an doppelten Positionen verworfen (die niedrigste Instanznummer behalten)</translation>
    </message>
    <message>
        <source>%1 missing slices (gaps up to %2 mm where the spacing is %3 mm): filled by interpolation</source>
        <translation>%1 fehlende Schichten (Lücken bis %2 mm bei einem Abstand von %3 mm): durch Interpolation aufgefüllt</translation>
    </message>
    <message>
        <source>uneven slice spacing (%1 to %2 mm): resampled to %3 mm</source>
        <translation>ungleichmäßiger Schichtabstand (%1 bis %2 mm): auf %3 mm umgetastet</translation>
    </message>
    <message>
        <source>gantry tilt of %1 degrees: resampled onto an orthogonal grid</source>
        <translation>Gantry-Neigung von %1 Grad: auf ein orthogonales Gitter umgetastet</translation>
    </message>
    <message>
        <source>the series has a single slice</source>
        <translation>die Serie hat nur eine Schicht</translation>
    </message>
    <message>
        <source>the lowest renal artery was not found in the lumen label: the neck is the narrowest outer diameter within 80 mm above the widest section</source>
        <translation>die unterste Nierenarterie wurde im Lumenlabel nicht gefunden: der Hals ist der kleinste Außendurchmesser innerhalb von 80 mm über dem weitesten Querschnitt</translation>
    </message>
    <message>
        <source>no sac: the widest outer diameter does not exceed 1.5 x the neck&apos;s</source>
        <translation>kein Sack: der größte Außendurchmesser übersteigt nicht das 1,5-Fache des Halses</translation>
    </message>
    <message>
        <source>the fronts reached the path-length limit (%1 mm) or a branch limit: the vessel continues beyond the label</source>
        <translation>die Fronten erreichten die Weglängengrenze (%1 mm) oder eine Verzweigungsgrenze: das Gefäß setzt sich über das Label hinaus fort</translation>
    </message>
    <message>
        <source>the opening removed every point&apos;s surroundings: the lesion is thinner than the opening there; the label is the grown region without the opening</source>
        <translation>die Öffnung entfernte die Umgebung jedes Punkts: die Läsion ist dort dünner als die Öffnung; das Label ist die gewachsene Region ohne Öffnung</translation>
    </message>
    <message>
        <source>the opening removed every point&apos;s surroundings: the organ is thinner than the opening there; the label is the grown region without the opening</source>
        <translation>die Öffnung entfernte die Umgebung jedes Punkts: das Organ ist dort dünner als die Öffnung; das Label ist die gewachsene Region ohne Öffnung</translation>
    </message>
    <message>
        <source>weak contrast: blood %1 HU against tissue %2 HU; the boundary may be unreliable</source>
        <translation>schwacher Kontrast: Blut %1 HU gegen Gewebe %2 HU; die Grenze ist womöglich unzuverlässig</translation>
    </message>
    <message>
        <source>%1 voxels next to bone or calcium excluded</source>
        <translation>%1 Voxel neben Knochen oder Kalk ausgeschlossen</translation>
    </message>
    <message>
        <source>%1 boundary faces outside the selection have all their nodes on the lumen surface and carry the pressure too (a wall one element thick there)</source>
        <translation>%1 Randflächen außerhalb der Auswahl liegen mit allen Knoten auf der Lumenoberfläche und tragen ebenfalls den Druck (dort ist die Wand nur ein Element dick)</translation>
    </message>
    <message>
        <source>%1 triangles in loose pieces left by the end cuts (or apart from the vessel tree) were dropped</source>
        <translation>%1 Dreiecke in losen Stücken, die die Endschnitte hinterließen (oder abseits des Gefäßbaums), wurden verworfen</translation>
    </message>
    <message>
        <source>the lumen surface is open away from the vessel ends (%1 boundary edges; is the segmentation cut by the image border?): those nodes stay free</source>
        <translation>die Lumenoberfläche ist abseits der Gefäßenden offen (%1 Randkanten; schneidet der Bildrand die Segmentierung?): diese Knoten bleiben frei</translation>
    </message>
    <message>
        <source>%1 elements are inverted where the offset folds (wall thicker than the local radius of curvature): use a thinner wall or a smoother surface</source>
        <translation>%1 Elemente sind umgestülpt, wo sich der Versatz faltet (Wand dicker als der lokale Krümmungsradius): verwenden Sie eine dünnere Wand oder eine glattere Oberfläche</translation>
    </message>
    <message>
        <source>end %1 has no open boundary</source>
        <translation>Ende %1 hat keinen offenen Rand</translation>
    </message>
    <message>
        <source>a value that is not finite: %1</source>
        <translation>ein nicht endlicher Wert: %1</translation>
    </message>
    <message>
        <source>the run did not reach its end within the step limit of %1 steps (a collapsing time step?)</source>
        <translation>der Lauf erreichte sein Ende nicht innerhalb der Schrittgrenze von %1 Schritten (ein zusammenbrechender Zeitschritt?)</translation>
    </message>
    <message>
        <source>step %1 left %2</source>
        <translation>Schritt %1 hinterließ %2</translation>
    </message>
    <message>
        <source>the equilibrium at the ramp&apos;s start %1 failed: %2</source>
        <translation>das Gleichgewicht am Beginn der Rampe %1 schlug fehl: %2</translation>
    </message>
    <message>
        <source>elements are over the tear strength already at the ramp&apos;s start %1: start lower</source>
        <translation>Elemente liegen schon am Beginn der Rampe %1 über der Reißfestigkeit: beginnen Sie niedriger</translation>
    </message>
    <message>
        <source>no equilibrium in %1 Newton updates (force residual %2)</source>
        <translation>kein Gleichgewicht in %1 Newton-Schritten (Kraftresiduum %2)</translation>
    </message>
    <message>
        <source>the equilibrium at %1 failed: %2</source>
        <translation>das Gleichgewicht bei %1 schlug fehl: %2</translation>
    </message>
    <message>
        <source>the fracture entropy passed %1 nats at %2</source>
        <translation>die Bruchentropie überschritt %1 nats bei %2</translation>
    </message>
    <message>
        <source>%1 elements torn at %2</source>
        <translation>%1 Elemente gerissen bei %2</translation>
    </message>
    <message>
        <source>the torn wall holds no equilibrium at %1 (rupture): %2</source>
        <translation>die gerissene Wand hat bei %1 kein Gleichgewicht (Ruptur): %2</translation>
    </message>
    <message>
        <source>the equilibrium at %1 % of the pressure did not converge in %2 Newton updates (force residual %3) even in increments of 1/16; the last converged increment is kept</source>
        <translation>das Gleichgewicht bei %1 % des Drucks konvergierte nicht in %2 Newton-Schritten (Kraftresiduum %3), auch nicht in Inkrementen von 1/16; das letzte konvergierte Inkrement bleibt erhalten</translation>
    </message>
    <message>
        <source>the equilibrium at %1 % of the pressure failed: %2 even in increments of 1/16; the last converged increment is kept</source>
        <translation>das Gleichgewicht bei %1 % des Drucks schlug fehl: %2, auch in Inkrementen von 1/16; das letzte konvergierte Inkrement bleibt erhalten</translation>
    </message>
    <message>
        <source>%1 at step %2 (t = %3 s, pressure %4 MPa); the last good state is kept</source>
        <translation>%1 in Schritt %2 (t = %3 s, Druck %4 MPa); der letzte gültige Zustand bleibt erhalten</translation>
    </message>
    <message>
        <source>%1 at step %2; the last good state is kept</source>
        <translation>%1 in Schritt %2; der letzte gültige Zustand bleibt erhalten</translation>
    </message>
    <message>
        <source>the fracture entropy reached %1 (end condition %2)</source>
        <translation>die Bruchentropie erreichte %1 (Endbedingung %2)</translation>
    </message>
    <message>
        <source>the equilibrium solve failed (%1); the figures are the load path&apos;s</source>
        <translation>die Gleichgewichtslösung schlug fehl (%1); die Kennzahlen sind die des Lastpfads</translation>
    </message>
    <message>
        <source>%1 elements inverted (the first near %2, %3, %4 mm)</source>
        <translation>%1 Elemente umgestülpt (das erste nahe %2, %3, %4 mm)</translation>
    </message>
    <message>
        <source>the solution is no longer finite (NaN or infinity)</source>
        <translation>die Lösung ist nicht mehr endlich (NaN oder unendlich)</translation>
    </message>
    <message>
        <source>the conjugate gradients broke down (the system is not positive definite)</source>
        <translation>die konjugierten Gradienten sind zusammengebrochen (das System ist nicht positiv definit)</translation>
    </message>
    <message>
        <source>at t = %1 s the temperature rise at node (%2, %3, %4) reached %5 K, above the initial maximum %6 K: the explicit step is unstable (time step %7 s; the stability limit is h^2/(6D) = %8 s)</source>
        <translation>bei t = %1 s erreichte der Temperaturanstieg am Knoten (%2, %3, %4) %5 K, über dem anfänglichen Maximum %6 K: der explizite Schritt ist instabil (Zeitschritt %7 s; die Stabilitätsgrenze ist h^2/(6D) = %8 s)</translation>
    </message>
    <message>
        <source>the injection (%1 ml/min) is at least the vessel&apos;s own flow at the tip (%2 ml/min)</source>
        <translation>die Injektion (%1 ml/min) ist mindestens so groß wie der eigene Fluss des Gefäßes an der Spitze (%2 ml/min)</translation>
    </message>
    <message>
        <source>the catheter fills %1 % of the lumen at the tip</source>
        <translation>der Katheter füllt %1 % des Lumens an der Spitze</translation>
    </message>
    <message>
        <source>the Reynolds number reaches %1: the flow may not be laminar there, and Hagen-Poiseuille does not hold</source>
        <translation>die Reynolds-Zahl erreicht %1: die Strömung ist dort womöglich nicht laminar, und Hagen-Poiseuille gilt nicht</translation>
    </message>
    <message>
        <source>wedged catheter: %1; the injection refluxes or stops the blood flow at the tip</source>
        <translation>verkeilter Katheter: %1; die Injektion fließt zurück oder stoppt den Blutfluss an der Spitze</translation>
    </message>
    <message>
        <source>%1 % of the injected drug refluxes past the catheter&apos;s tip (non-target delivery)</source>
        <translation>%1 % des injizierten Wirkstoffs fließen an der Katheterspitze zurück (Fehlembolisation)</translation>
    </message>
    <message>
        <source>a void fraction of %1 is past bubbly flow (about 0.25): the homogeneous model and the thesis&apos;s experiment do not cover it</source>
        <translation>ein Gasanteil von %1 liegt jenseits der Blasenströmung (etwa 0,25): das homogene Modell und das Experiment der Dissertation decken ihn nicht ab</translation>
    </message>
    <message>
        <source>coverage grade C from this tip: part of a lesion is not perfused (see the feeders)</source>
        <translation>Abdeckungsgrad C von dieser Spitze: ein Teil einer Läsion wird nicht perfundiert (siehe die Zuflüsse)</translation>
    </message>
    <message>
        <source>no outlet of the tree ends inside the tumour: nothing feeds it</source>
        <translation>kein Auslass des Baums endet im Tumor: nichts versorgt ihn</translation>
    </message>
    <message>
        <source>the flow is no longer finite at t = %1 s</source>
        <translation>die Strömung ist bei t = %1 s nicht mehr endlich</translation>
    </message>
    <message>
        <source>the flow crossed %1 cells in one step at t = %2 s (the limit is %3): the run is unstable (too strong a confinement or vortex forcing, or too long a step)</source>
        <translation>die Strömung durchquerte bei t = %2 s %1 Zellen in einem Schritt (die Grenze ist %3): der Lauf ist instabil (zu starke Confinement- oder Wirbelkraft oder zu langer Schritt)</translation>
    </message>
    <message>
        <source>(sorting the particles): %1</source>
        <translation>(beim Sortieren der Teilchen): %1</translation>
    </message>
    <message>
        <source>fluid particle %1 went %2 mm into the wall at %3: the time step or the sound speed is too large for the flow, or the wall thinner than the kernel (a segmentation&apos;s ragged edge: the walls&apos; backstop, parameter wall_repulsion 0.01)</source>
        <translation>Fluidteilchen %1 drang bei %3 %2 mm in die Wand ein: Zeitschritt oder Schallgeschwindigkeit sind zu groß für die Strömung, oder die Wand ist dünner als der Kern (ein ausgefranster Segmentierungsrand: die Rückhaltung der Wände, Parameter wall_repulsion 0,01)</translation>
    </message>
    <message>
        <source>%1 mm from the wall</source>
        <translation>%1 mm von der Wand</translation>
    </message>
    <message>
        <source>particle %1&apos;s density is %2 % from the rest density (guard %3 %) at %4, %5: raise the sound speed or lower the inflow</source>
        <translation>die Dichte von Teilchen %1 weicht %2 % von der Ruhedichte ab (Wächter %3 %) bei %4, %5: erhöhen Sie die Schallgeschwindigkeit oder senken Sie den Zufluss</translation>
    </message>
    <message>
        <source>away from the walls</source>
        <translation>abseits der Wände</translation>
    </message>
    <message>
        <source>the mask was on another grid of the same scan (offset %1, %2, %3 voxels): cut to the image&apos;s grid, every labelled voxel kept</source>
        <translation>die Maske lag auf einem anderen Gitter desselben Scans (Versatz %1, %2, %3 Voxel): auf das Gitter des Bildes zugeschnitten, jedes markierte Voxel behalten</translation>
    </message>
    <message>
        <source>the mask&apos;s voxels were stored in another axis order or direction: reordered onto the image&apos;s grid, voxel for voxel</source>
        <translation>die Voxel der Maske waren in anderer Achsenreihenfolge oder Richtung gespeichert: Voxel für Voxel auf das Gitter des Bildes umgeordnet</translation>
    </message>
    <message>
        <source>a frame of the run is missing: %1</source>
        <translation>ein Bild des Laufs fehlt: %1</translation>
    </message>
    <message>
        <source>a frame of the run differs from its record (damaged): %1</source>
        <translation>ein Bild des Laufs weicht von seinem Eintrag ab (beschädigt): %1</translation>
    </message>
    <message>
        <source>file is missing: %1</source>
        <translation>Datei fehlt: %1</translation>
    </message>
    <message>
        <source>file size differs from the manifest: %1</source>
        <translation>Dateigröße weicht vom Manifest ab: %1</translation>
    </message>
    <message>
        <source>file checksum differs from the manifest (damaged): %1</source>
        <translation>Prüfsumme der Datei weicht vom Manifest ab (beschädigt): %1</translation>
    </message>
    <message>
        <source>artifact &apos;%1&apos; (%2): %3</source>
        <translation>Artefakt „%1“ (%2): %3</translation>
    </message>
    <message>
        <source>leftover of an interrupted save, removed at the next save: %1</source>
        <translation>Rest eines unterbrochenen Speicherns, wird beim nächsten Speichern entfernt: %1</translation>
    </message>
    <message>
        <source>%1 voxels were not whole numbers and were rounded to integer HU</source>
        <translation>%1 Voxel waren keine ganzen Zahlen und wurden auf ganzzahlige HU gerundet</translation>
    </message>
    <message>
        <source>%1 voxels were outside the int16 range or not finite and were clamped</source>
        <translation>%1 Voxel lagen außerhalb des int16-Bereichs oder waren nicht endlich und wurden begrenzt</translation>
    </message>
    <message>
        <source>clamped 0.5 x 0.1 x 0.1 m beam (70 x 14 x 14 cells, %1 tets, E = 1 MPa, nu = 0) with a tip load: mean tip deflection against Timoshenko theory P L^3 / (3 E I) + P L / (k G A), k = 10 (1 + nu) / (12 + 11 nu)</source>
        <translation>eingespannter Balken 0,5 x 0,1 x 0,1 m (70 x 14 x 14 Zellen, %1 Tetraeder, E = 1 MPa, nu = 0) mit Endlast: mittlere Endauslenkung gegen die Timoshenko-Theorie P L^3 / (3 E I) + P L / (k G A), k = 10 (1 + nu) / (12 + 11 nu)</translation>
    </message>
    <message>
        <source>quarter of a thick-walled tube (a = 10 mm, b = 20 mm, %1 tets, E = 1 MPa, nu = 0.45) under 1 kPa inside, plane strain and symmetry planes: radial displacement and hoop stress against Lame&apos;s solution</source>
        <translation>Viertel eines dickwandigen Rohrs (a = 10 mm, b = 20 mm, %1 Tetraeder, E = 1 MPa, nu = 0,45) unter 1 kPa Innendruck, ebener Dehnungszustand und Symmetrieebenen: radiale Verschiebung und Umfangsspannung gegen die Lösung von Lamé</translation>
    </message>
    <message>
        <source>quarter of a thick-walled tube (a = 10 mm, b = 20 mm, %1 quadratic tets, E = 1 MPa, nu = 0.49, nearly incompressible) under 1 kPa inside (follower), plane strain and symmetry planes, Newton to 1e-8: radial displacement and the elements&apos; hoop stress (mean of the 4 quadrature points, no averaging over cells) against Lame&apos;s solution</source>
        <translation>Viertel eines dickwandigen Rohrs (a = 10 mm, b = 20 mm, %1 quadratische Tetraeder, E = 1 MPa, nu = 0,49, nahezu inkompressibel) unter 1 kPa Innendruck (mitgehend), ebener Dehnungszustand und Symmetrieebenen, Newton bis 1e-8: radiale Verschiebung und die Umfangsspannung der Elemente (Mittel der 4 Quadraturpunkte, keine Mittelung über Zellen) gegen die Lösung von Lamé</translation>
    </message>
    <message>
        <source>constant-strain patch: boundary nodes of a 4x4x4-cell cube (384 tets) moved by u = A X + c, interior solved; interior displacement and element stress against the exact linear field</source>
        <translation>Patch-Test mit konstanter Dehnung: Randknoten eines Würfels aus 4x4x4 Zellen (384 Tetraeder) um u = A X + c verschoben, das Innere gelöst; innere Verschiebung und Elementspannung gegen das exakte lineare Feld</translation>
    </message>
    <message>
        <source>a 0.1 x 0.05 x 0.05 m block (96 tets, E = 1 MPa) turned 90 degrees about z and moved: largest elastic force against E h^2 (h = element size)</source>
        <translation>ein Block 0,1 x 0,05 x 0,05 m (96 Tetraeder, E = 1 MPa), um 90 Grad um z gedreht und verschoben: größte elastische Kraft gegen E h^2 (h = Elementgröße)</translation>
    </message>
    <message>
        <source>a 0.2 m cantilever (240 tets) bent by a tip load, released without load; backward Euler, h = 1 ms, 300 steps, Rayleigh beta = 0.22 s (thesis) and 0.005 s: total energy (kinetic + elastic) must never rise</source>
        <translation>ein 0,2-m-Kragbalken (240 Tetraeder), durch eine Endlast gebogen und ohne Last losgelassen; implizites Euler-Verfahren, h = 1 ms, 300 Schritte, Rayleigh-beta = 0,22 s (Dissertation) und 0,005 s: die Gesamtenergie (kinetisch + elastisch) darf nie steigen</translation>
    </message>
    <message>
        <source>the slowest mode of a 20 mm cube of tissue (D 0.14 mm^2/s) after one decay time, on the run driver: relative L2 error against the exact solution, and its order of convergence</source>
        <translation>die langsamste Mode eines 20-mm-Gewebewürfels (D 0,14 mm^2/s) nach einer Abklingzeit, mit der Laufsteuerung: relativer L2-Fehler gegen die exakte Lösung und seine Konvergenzordnung</translation>
    </message>
    <message>
        <source>conical resistance with R1 = R2 against 8 mu L / (pi R^4)</source>
        <translation>konischer Widerstand mit R1 = R2 gegen 8 mu L / (pi R^4)</translation>
    </message>
    <message>
        <source>eq. 6.6 against eq. 6.4 integrated (Gauss-Legendre, 64 x 8 points)</source>
        <translation>Gl. 6.6 gegen die integrierte Gl. 6.4 (Gauß-Legendre, 64 x 8 Punkte)</translation>
    </message>
    <message>
        <source>Kirchhoff&apos;s law on a seeded random tree of 2,000 segments</source>
        <translation>Kirchhoffsches Gesetz an einem zufälligen Baum (fester Startwert) aus 2.000 Segmenten</translation>
    </message>
    <message>
        <source>tip -&gt; junction -&gt; two branches with terminal resistances into 1,000 and 2,000 Pa</source>
        <translation>Spitze -&gt; Verzweigung -&gt; zwei Äste mit Endwiderständen gegen 1.000 und 2.000 Pa</translation>
    </message>
    <message>
        <source>injected branch and a second inlet at 6,000 Pa joining before one outlet at 500 Pa</source>
        <translation>injizierter Ast und ein zweiter Einlass bei 6.000 Pa, die vor einem Auslass bei 500 Pa zusammenfließen</translation>
    </message>
    <message>
        <source>a catheter in a pipe: the annulus&apos;s Hagen-Poiseuille resistance</source>
        <translation>ein Katheter in einem Rohr: der Hagen-Poiseuille-Widerstand des Ringspalts</translation>
    </message>
    <message>
        <source>blood from the root and an injection at a tip, mixed at a confluence with a second inlet</source>
        <translation>Blut von der Wurzel und eine Injektion an einer Spitze, gemischt an einem Zusammenfluss mit einem zweiten Einlass</translation>
    </message>
    <message>
        <source>the injected mixture&apos;s viscosity shifts the split between the tip&apos;s branch and its sibling</source>
        <translation>die Viskosität des injizierten Gemischs verschiebt die Aufteilung zwischen dem Ast der Spitze und seinem Nachbarast</translation>
    </message>
    <message>
        <source>a puff of smoke (1e-3 kg/m^3, 30 K above the ambient, 0.15 m radius) rising by buoyancy in a closed 1 m box of 32^3 cells, 500 steps (the velocity by MacCormack with the limiter): the smoke mass at the end against the start, without renormalisation, moved by the limited finite-volume transport; moved by semi-Lagrangian MacCormack instead it drifted by %1 %</source>
        <translation>eine Rauchwolke (1e-3 kg/m^3, 30 K über der Umgebung, Radius 0,15 m), die durch Auftrieb in einer geschlossenen 1-m-Box aus 32^3 Zellen aufsteigt, 500 Schritte (die Geschwindigkeit mit MacCormack und Begrenzer): die Rauchmasse am Ende gegen den Anfang, ohne Renormierung, bewegt durch den begrenzten Finite-Volumen-Transport; mit semi-Lagrange-MacCormack bewegt, driftete sie stattdessen um %1 %</translation>
    </message>
    <message>
        <source>a random velocity field (uniform in +-1 m/s on the faces) in a 1 m box of 48^3 cells, walls with an open top and a solid sphere of 0.15 m radius at the centre, projected by MGPCG to a relative residual of 1e-6 on three seeds: the largest |div u| h / max |u| left</source>
        <translation>ein zufälliges Geschwindigkeitsfeld (gleichverteilt in +-1 m/s auf den Flächen) in einer 1-m-Box aus 48^3 Zellen, Wände mit offener Oberseite und einer festen Kugel mit 0,15 m Radius in der Mitte, mit MGPCG auf ein relatives Residuum von 1e-6 projiziert, drei Startwerte: das größte verbleibende |div u| h / max |u|</translation>
    </message>
    <message>
        <source>the inviscid Taylor-Green vortex u = (sin x cos y cos z, -cos x sin y cos z, 0) (pi/m, 1 m/s) in a 1 m free-slip box of 32^3 cells for 1 s: the effective numerical viscosity -(dE/dt) / integral |w|^2 with vorticity confinement (epsilon 0.5) and with vortex particles (epsilon 0.5, r = 2 h) against the plain semi-Lagrangian scheme</source>
        <translation>der reibungsfreie Taylor-Green-Wirbel u = (sin x cos y cos z, -cos x sin y cos z, 0) (pi/m, 1 m/s) in einer reibungsfrei berandeten 1-m-Box aus 32^3 Zellen für 1 s: die effektive numerische Viskosität -(dE/dt) / Integral |w|^2 mit Wirbelstärkeverstärkung (epsilon 0,5) und mit Wirbelteilchen (epsilon 0,5, r = 2 h) gegen das einfache Semi-Lagrange-Verfahren</translation>
    </message>
    <message>
        <source>a ball of 0.1 m radius dropped from rest at 0.75 m in still air (a 1 m box of 48^3 cells, open at the top), falling under gravity for 0.25 s: the flow through the ball (the faces it touches against its own velocity), the divergence left around it, and the air pushed aside</source>
        <translation>eine Kugel mit 0,1 m Radius, aus der Ruhe in 0,75 m Höhe in ruhender Luft fallen gelassen (eine oben offene 1-m-Box aus 48^3 Zellen), 0,25 s unter Schwerkraft fallend: die Strömung durch die Kugel (die berührten Flächen gegen ihre eigene Geschwindigkeit), die verbleibende Divergenz um sie und die verdrängte Luft</translation>
    </message>
    <message>
        <source>water at rest in an open tank (8 x 8 x 16 particles of 1 mm, 4 wall layers) after 0.3 s under gravity, and the same tank of mixture particles at void fraction 0.2 (thesis Table 5.1): the pressure in the middle of the column, 2h below the surface and deeper, against the hydrostatic pressure of the model&apos;s fluid</source>
        <translation>ruhendes Wasser in einem offenen Behälter (8 x 8 x 16 Teilchen von 1 mm, 4 Wandschichten) nach 0,3 s unter Schwerkraft, und derselbe Behälter mit Gemischteilchen bei einem Gasanteil von 0,2 (Dissertation Tabelle 5.1): der Druck in der Mitte der Säule, 2h unter der Oberfläche und tiefer, gegen den hydrostatischen Druck des Modellfluids</translation>
    </message>
    <message>
        <source>%1 (%2 particles evaluated)</source>
        <translation>%1 (%2 Teilchen ausgewertet)</translation>
    </message>
    <message>
        <source>the 3D quartic kernel (h = 2 mm): its integral, W(2h), dW/dr against a central difference, and its first moment on a 1 mm particle lattice against the identity</source>
        <translation>der quartische 3D-Kern (h = 2 mm): sein Integral, W(2h), dW/dr gegen eine zentrale Differenz und sein erstes Moment auf einem 1-mm-Teilchengitter gegen die Identität</translation>
    </message>
    <message>
        <source>the gradient of a linear field at jittered particles (1 mm, +-0.2 mm) within h of a wall, three seeds: the first-order Finite Particle Method against the exact gradient, and plain SPH&apos;s error beside it</source>
        <translation>der Gradient eines linearen Felds an verrauschten Teilchen (1 mm, +-0,2 mm) innerhalb von h an einer Wand, drei Startwerte: die Finite-Teilchen-Methode erster Ordnung gegen den exakten Gradienten, daneben der Fehler des einfachen SPH</translation>
    </message>
    <message>
        <source>pipe 1 mm across, 2 mm long, velocity inlet (parabolic, mean 0.05 m/s, tracer) and pressure outlet, tracer absorbed within 0.1 mm of the wall, 6 ms: inflow %1 ug, outflow %2 ug, absorbed %3 ug, mass change %4 ug (%5 steps)</source>
        <translation>Rohr mit 1 mm Durchmesser, 2 mm lang, Geschwindigkeitseinlass (parabolisch, Mittel 0,05 m/s, Tracer) und Druckauslass, Tracer innerhalb von 0,1 mm an der Wand absorbiert, 6 ms: Zufluss %1 ug, Abfluss %2 ug, absorbiert %3 ug, Massenänderung %4 ug (%5 Schritte)</translation>
    </message>
    <message>
        <source>plane Poiseuille flow, 20 particles across a 2 mm channel (periodic along and across the flow, peak 0.1 m/s, Re 2), after 7 decay times: every fluid particle&apos;s velocity against the steady profile</source>
        <translation>ebene Poiseuille-Strömung, 20 Teilchen über einen 2-mm-Kanal (periodisch längs und quer zur Strömung, Spitze 0,1 m/s, Re 2), nach 7 Abklingzeiten: die Geschwindigkeit jedes Fluidteilchens gegen das stationäre Profil</translation>
    </message>
    <message>
        <source>50 % diameter cosine stenosis in a 1.6 mm pipe, 0.05 m/s mean inflow (Re 48 in the throat), averaged 15-25 ms: peak velocity ratio %1 upstream (%2 -&gt; %3 m/s), %4 downstream</source>
        <translation>50-%-Durchmesser-Kosinusstenose in einem 1,6-mm-Rohr, mittlerer Zufluss 0,05 m/s (Re 48 in der Engstelle), gemittelt über 15-25 ms: Spitzengeschwindigkeitsverhältnis %1 stromauf (%2 -&gt; %3 m/s), %4 stromab</translation>
    </message>
    <message>
        <source>mean ratio %1 (area ratio %2); pressure drop %3 Pa over 3.2 mm; throat wall shear stress %4 Pa (TAWSS); %5 steps, %6 particles</source>
        <translation>mittleres Verhältnis %1 (Flächenverhältnis %2); Druckabfall %3 Pa über 3,2 mm; Wandschubspannung in der Engstelle %4 Pa (TAWSS); %5 Schritte, %6 Teilchen</translation>
    </message>
    <message>
        <source>pulsatile flow in a rigid pipe 20 particles across (0.1 mm, periodic along its axis) from rest, alpha 4 (four cycles) and 8 (three): the velocity next to the axis over the last cycle against Womersley&apos;s solution</source>
        <translation>pulsierende Strömung in einem starren Rohr mit 20 Teilchen Durchmesser (0,1 mm, periodisch längs seiner Achse) aus der Ruhe, alpha 4 (vier Zyklen) und 8 (drei): die Geschwindigkeit nahe der Achse über den letzten Zyklus gegen die Womersley-Lösung</translation>
    </message>
    <message>
        <source>Vessel lumen</source>
        <translation>Gefäßlumen</translation>
    </message>
    <message>
        <source>Lumen surface</source>
        <translation>Lumenoberfläche</translation>
    </message>
    <message>
        <source>Vessel skeleton</source>
        <translation>Gefäßskelett</translation>
    </message>
    <message>
        <source>Centerlines</source>
        <translation>Mittellinien</translation>
    </message>
    <message>
        <source>Imported label</source>
        <translation>Importiertes Label</translation>
    </message>
    <message>
        <source>%1 (grown from one point)</source>
        <translation>%1 (aus einem Punkt gewachsen)</translation>
    </message>
    <message>
        <source>%1 (grown from %2 points)</source>
        <translation>%1 (aus %2 Punkten gewachsen)</translation>
    </message>
    <message>
        <source>Cloth sheet</source>
        <translation>Tuch</translation>
    </message>
    <message>
        <source>Imported wall</source>
        <translation>Importierte Wand</translation>
    </message>
    <message>
        <source>Blood flow (SPH)</source>
        <translation>Blutfluss (SPH)</translation>
    </message>
    <message>
        <source>Wall loads (SPH)</source>
        <translation>Wandlasten (SPH)</translation>
    </message>
    <message>
        <source>DICOM series %1</source>
        <translation>DICOM-Serie %1</translation>
    </message>
    <message>
        <source>Vessel lumen (aorta)</source>
        <translation>Gefäßlumen (Aorta)</translation>
    </message>
    <message>
        <source>Vessel lumen (hepatic arteries)</source>
        <translation>Gefäßlumen (Leberarterien)</translation>
    </message>
    <message>
        <source>Vessel lumen (from points)</source>
        <translation>Gefäßlumen (aus Punkten)</translation>
    </message>
    <message>
        <source>Needle injection (SPH)</source>
        <translation>Nadelinjektion (SPH)</translation>
    </message>
    <message>
        <source>Drug filling</source>
        <translation>Wirkstofffüllung</translation>
    </message>
    <message>
        <source>Drug flow</source>
        <translation>Wirkstofffluss</translation>
    </message>
    <message>
        <source>AAA sac (lumen 1, thrombus 4, wall 5)</source>
        <translation>AAA-Sack (Lumen 1, Thrombus 4, Wand 5)</translation>
    </message>
    <message>
        <source>Surgical smoke (%1, illustrative)</source>
        <translation>Chirurgischer Rauch (%1, veranschaulichend)</translation>
    </message>
    <message>
        <source>Report (anonymized)</source>
        <translation>Bericht (anonymisiert)</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <source>Wall run (%1)</source>
        <translation>Wandlauf (%1)</translation>
    </message>
    <message>
        <source>Wall stress (%1)</source>
        <translation>Wandspannung (%1)</translation>
    </message>
    <message>
        <source>Vessel wall</source>
        <translation>Gefäßwand</translation>
    </message>
    <message>
        <source>Ruler %1: %2</source>
        <translation>Lineal %1: %2</translation>
    </message>
    <message>
        <source>Angle %1: %2</source>
        <translation>Winkel %1: %2</translation>
    </message>
    <message>
        <source>ROI %1: %2</source>
        <translation>ROI %1: %2</translation>
    </message>
    <message>
        <source>mean %1 HU, SD %2 HU, area %3 mm2</source>
        <translation>Mittel %1 HU, SD %2 HU, Fläche %3 mm2</translation>
    </message>
    <message>
        <source>physiological</source>
        <translation>physiologisch</translation>
    </message>
    <message>
        <source>thesis-rupture</source>
        <translation>Ruptur nach der Dissertation</translation>
    </message>
    <message>
        <source>interactive</source>
        <translation>interaktiv</translation>
    </message>
    <message>
        <source>tumour</source>
        <translation>Tumor</translation>
    </message>
    <message>
        <source>liver</source>
        <translation>Leber</translation>
    </message>
    <message>
        <source>ball drop</source>
        <translation>Kugelfall</translation>
    </message>
    <message>
        <source>endoscopic vessel harvesting</source>
        <translation>endoskopische Gefäßentnahme</translation>
    </message>
    <message>
        <source>liver ablation</source>
        <translation>Leberablation</translation>
    </message>
    <message>
        <source>unnamed (nodes %1-%2)</source>
        <translation>unbenannt (Knoten %1-%2)</translation>
    </message>
    <message>
        <source>%1 at %2:%3 (TLS)</source>
        <translation>%1 auf %2:%3 (TLS)</translation>
    </message>
    <message>
        <source>%1 at %2:%3</source>
        <translation>%1 auf %2:%3</translation>
    </message>
    <message>
        <source>aorta</source>
        <translation>Aorta</translation>
    </message>
    <message>
        <source>left common iliac artery</source>
        <translation>linke A. iliaca communis</translation>
    </message>
    <message>
        <source>right common iliac artery</source>
        <translation>rechte A. iliaca communis</translation>
    </message>
    <message>
        <source>left renal artery</source>
        <translation>linke Nierenarterie</translation>
    </message>
    <message>
        <source>right renal artery</source>
        <translation>rechte Nierenarterie</translation>
    </message>
    <message>
        <source>superior mesenteric artery</source>
        <translation>A. mesenterica superior</translation>
    </message>
    <message>
        <source>celiac trunk</source>
        <translation>Truncus coeliacus</translation>
    </message>
    <message>
        <source>splenic artery</source>
        <translation>A. lienalis</translation>
    </message>
    <message>
        <source>common hepatic artery</source>
        <translation>A. hepatica communis</translation>
    </message>
    <message>
        <source>gastroduodenal artery</source>
        <translation>A. gastroduodenalis</translation>
    </message>
    <message>
        <source>proper hepatic artery</source>
        <translation>A. hepatica propria</translation>
    </message>
    <message>
        <source>right hepatic artery</source>
        <translation>A. hepatica dextra</translation>
    </message>
    <message>
        <source>left hepatic artery</source>
        <translation>A. hepatica sinistra</translation>
    </message>
    <message>
        <source>segmental hepatic artery</source>
        <translation>segmentale Leberarterie</translation>
    </message>
    <message>
        <source>this model does not solve its own tangent</source>
        <translation>dieses Modell löst seine Tangente nicht selbst</translation>
    </message>
    <message>
        <source>a model that solves its own tangent (the GPU) takes the conjugate-gradient static solve</source>
        <translation>ein Modell, das seine Tangente selbst löst (die GPU), verlangt die statische Lösung mit konjugierten Gradienten</translation>
    </message>
    <message>
        <source>the multigrid preconditioner needs the model&apos;s positions</source>
        <translation>der Mehrgitter-Vorkonditionierer braucht die Positionen des Modells</translation>
    </message>
    <message>
        <source>the static solve on the GPU is the modified Newton iteration with multigrid conjugate gradients</source>
        <translation>die statische Lösung auf der GPU ist die modifizierte Newton-Iteration mit Mehrgitter-konjugierten Gradienten</translation>
    </message>
    <message>
        <source>the static wall on the GPU was made for another mesh</source>
        <translation>die statische Wand auf der GPU wurde für ein anderes Netz angelegt</translation>
    </message>
    <message>
        <source>the mask holds one value (%1): stored as label 1, the lumen&apos;s (give --label-value N for another)</source>
        <translation>die Maske enthält einen Wert (%1): als Label 1 gespeichert, das des Lumens (--label-value N für ein anderes)</translation>
    </message>
    <message>
        <source>particle shifting (particle_shifting &gt; 0) needs a fluid that fills its vessel: a free surface (free_surface 1) or a fluid without tension (fluid_tension 0) would be pushed apart at its edge; set particle_shifting 0</source>
        <translation>Partikelverschiebung (particle_shifting &gt; 0) braucht ein Fluid, das sein Gefäß füllt: eine freie Oberfläche (free_surface 1) oder ein Fluid ohne Zugspannung (fluid_tension 0) würde an seinem Rand auseinandergedrückt; particle_shifting 0 setzen</translation>
    </message>
    <message>
        <source>the saved section averages are for %1 sections, this run has %2</source>
        <translation>die gespeicherten Querschnittsmittel gelten für %1 Querschnitte, dieser Lauf hat %2</translation>
    </message>
    <message>
        <source>the saved run has %1 open boundaries, this run %2: the checkpoint belongs to another problem</source>
        <translation>der gespeicherte Lauf hat %1 offene Ränder, dieser Lauf %2: der Sicherungspunkt gehört zu einem anderen Problem</translation>
    </message>
    <message>
        <source>the SPH checkpoint is cut short or damaged</source>
        <translation>der SPH-Sicherungspunkt ist abgeschnitten oder beschädigt</translation>
    </message>
    <message>
        <source>will not replace a file that is not an SPH checkpoint</source>
        <translation>eine Datei, die kein SPH-Sicherungspunkt ist, wird nicht ersetzt</translation>
    </message>
    <message>
        <source>cannot write the SPH checkpoint</source>
        <translation>der SPH-Sicherungspunkt kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>cannot open the SPH checkpoint</source>
        <translation>der SPH-Sicherungspunkt kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>not an SPH checkpoint of this version (its first line is not &apos;VSIM-SPH-CHECKPOINT 2&apos;)</source>
        <translation>kein SPH-Sicherungspunkt dieser Version (seine erste Zeile ist nicht &apos;VSIM-SPH-CHECKPOINT 2&apos;)</translation>
    </message>
    <message>
        <source>the saved run&apos;s wall particle %1 is not this run&apos;s: the checkpoint belongs to another problem</source>
        <translation>das Wandpartikel %1 des gespeicherten Laufs gehört nicht zu diesem Lauf: der Sicherungspunkt gehört zu einem anderen Problem</translation>
    </message>
    <message>
        <source>the saved run has %1 wall particles, this run %2: the checkpoint belongs to another problem</source>
        <translation>der gespeicherte Lauf hat %1 Wandpartikel, dieser Lauf %2: der Sicherungspunkt gehört zu einem anderen Problem</translation>
    </message>
    <message>
        <source>the saved wall-load averages are for %1 points, this run has %2</source>
        <translation>die gespeicherten Wandlastmittel gelten für %1 Punkte, dieser Lauf hat %2</translation>
    </message>
    <message>
        <source>the saved rates do not fit the particles: the checkpoint is damaged</source>
        <translation>die gespeicherten Raten passen nicht zu den Partikeln: der Sicherungspunkt ist beschädigt</translation>
    </message>
    <message>
        <source>the saved run shifted its particles and this run does not (particle_shifting 0): the checkpoint belongs to another problem</source>
        <translation>der gespeicherte Lauf hat seine Partikel verschoben und dieser Lauf nicht (particle_shifting 0): der Sicherungspunkt gehört zu einem anderen Problem</translation>
    </message>
    <message>
        <source>this run shifts its particles (particle_shifting) and the saved run did not: the checkpoint belongs to another problem</source>
        <translation>dieser Lauf verschiebt seine Partikel (particle_shifting) und der gespeicherte Lauf nicht: der Sicherungspunkt gehört zu einem anderen Problem</translation>
    </message>
    <message>
        <source>the dam break experiment&apos;s record does not cover that time</source>
        <translation>die Aufzeichnung des Dammbruch-Experiments reicht nicht bis zu diesem Zeitpunkt</translation>
    </message>
    <message>
        <source>sph-dambreak needs a GPU at its million particles (about 20 hours on 2 CPU cores): %1; validate sph-dambreak --backend cpu [--particles N] runs it on the CPU</source>
        <translation>sph-dambreak braucht bei seiner Million Partikel eine GPU (etwa 20 Stunden auf 2 CPU-Kernen): %1; validate sph-dambreak --backend cpu [--particles N] rechnet es auf der CPU</translation>
    </message>
    <message>
        <source>the dam break&apos;s end must lie within the experiment&apos;s record (0 to %1 s)</source>
        <translation>das Ende des Dammbruchs muss innerhalb der Aufzeichnung des Experiments liegen (0 bis %1 s)</translation>
    </message>
    <message>
        <source>SPHERIC benchmark 2 (Kleefsman et al. 2005): the dam break with the obstacle, %1 particles (%2 walls) at %3 mm, c0 %4 m/s, on the %5; the water heights at the probes H1-H4 every 20 ms against MARIN&apos;s record (this project&apos;s tolerance: RMS within 10 % of the 0.55 m column, fronts within 50 ms, the whole record run)%6</source>
        <translation>SPHERIC-Benchmark 2 (Kleefsman et al. 2005): der Dammbruch mit dem Hindernis, %1 Partikel (%2 Wandpartikel) bei %3 mm, c0 %4 m/s, auf der %5; die Wasserhöhen an den Sonden H1-H4 alle 20 ms gegen die Aufzeichnung von MARIN (Toleranz dieses Projekts: RMS innerhalb 10 % der 0,55-m-Säule, Fronten innerhalb 50 ms, die ganze Aufzeichnung gerechnet)%6</translation>
    </message>
    <message>
        <source>; stopped by a guard: %1</source>
        <translation>; von einem Wächter angehalten: %1</translation>
    </message>
    <message>
        <source>dam break</source>
        <translation>Dammbruch</translation>
    </message>
    <message>
        <source>GPU (single precision)</source>
        <translation>GPU (einfache Genauigkeit)</translation>
    </message>
    <message>
        <source>CPU (double precision)</source>
        <translation>CPU (doppelte Genauigkeit)</translation>
    </message>
    <message>
        <source>a pulsatile inflow needs a period &gt; 0 s and an amplitude in [0, 1), not %1 s and %2</source>
        <translation>ein pulsierender Einstrom braucht eine Periode &gt; 0 s und eine Amplitude in [0, 1), nicht %1 s und %2</translation>
    </message>
    <message>
        <source>the SPH input gives some of the particles&apos; velocity components, not all three: give velocity_x_m_s, velocity_y_m_s and velocity_z_m_s together</source>
        <translation>die SPH-Eingabe gibt nur einen Teil der Geschwindigkeitskomponenten der Partikel an, nicht alle drei: velocity_x_m_s, velocity_y_m_s und velocity_z_m_s zusammen angeben</translation>
    </message>
    <message>
        <source>the open boundary &apos;%1&apos; has buffer particles down to %2 mm behind its plane, and its buffer must be as deep as the kernel&apos;s support, %3 mm (2 x the smoothing ratio x the spacing): seed it for this smoothing ratio</source>
        <translation>die offene Grenze &apos;%1&apos; hat Pufferpartikel bis %2 mm hinter ihrer Ebene, und ihr Puffer muss so tief sein wie der Träger des Kerns, %3 mm (2 x das Glättungsverhältnis x der Abstand): für dieses Glättungsverhältnis neu besetzen</translation>
    </message>
    <message>
        <source>density by summation (density_summation 1) needs a fluid that fills its vessel: at a free surface (free_surface 1) or the edge of a liquid without tension (fluid_tension 0) the particles&apos; sums fall short and would read as suction; set density_summation 0</source>
        <translation>die Dichte durch Summation (density_summation 1) braucht ein Fluid, das sein Gefäß füllt: an einer freien Oberfläche (free_surface 1) oder am Rand einer Flüssigkeit ohne Zug (fluid_tension 0) fallen die Summen der Partikel zu klein aus und wirkten als Sog; setzen Sie density_summation 0</translation>
    </message>
    <message>
        <source>the Finite Particle Method (fpm 1) corrects the continuity equation&apos;s density rate, which density by summation (density_summation 1) does not use: set one of them to 0</source>
        <translation>die Finite-Partikel-Methode (fpm 1) korrigiert die Dichterate der Kontinuitätsgleichung, die die Dichte durch Summation (density_summation 1) nicht verwendet: setzen Sie eines von beiden auf 0</translation>
    </message>
    <message>
        <source>the density&apos;s relaxation towards summation (density_relaxation_s &gt; 0) is for the continuity density (density_summation 0) of a fluid that fills its vessel (free_surface 0, fluid_tension 1): set density_relaxation_s 0</source>
        <translation>die Relaxation der Dichte zur Summation (density_relaxation_s &gt; 0) gilt der Kontinuitätsdichte (density_summation 0) eines Fluids, das sein Gefäß füllt (free_surface 0, fluid_tension 1): setzen Sie density_relaxation_s 0</translation>
    </message>
    <message>
        <source>at t = %1 s the vessel has lost %2 % of its first fluid mass through its open ends (outflow - inflow; fluid_loss_guard %3 %): its particles no longer fill it, so its figures would not be a flow&apos;s; relax the density towards summation (density_relaxation_s) or raise the sound speed</source>
        <translation>bei t = %1 s hat das Gefäß %2 % seiner anfänglichen Fluidmasse durch seine offenen Enden verloren (Ausfluss - Zufluss; fluid_loss_guard %3 %): seine Partikel füllen es nicht mehr, seine Werte wären also nicht die einer Strömung; lassen Sie die Dichte zur Summation relaxieren (density_relaxation_s) oder erhöhen Sie die Schallgeschwindigkeit</translation>
    </message>
    <message>
        <source>the SPH input&apos;s particles carry the field &apos;%1&apos;, which the solver does not read (it reads wall, wall_depth_mm, open_boundary, tracer, pressure_pa, velocity_x_m_s, velocity_y_m_s, velocity_z_m_s and void_fraction): is it misspelt?</source>
        <translation>die Partikel der SPH-Eingabe tragen das Feld &apos;%1&apos;, das der Löser nicht liest (er liest wall, wall_depth_mm, open_boundary, tracer, pressure_pa, velocity_x_m_s, velocity_y_m_s, velocity_z_m_s und void_fraction): ist es falsch geschrieben?</translation>
    </message>
    <message>
        <source>the wall loads %1 have no wall_pressure_pa</source>
        <translation>die Wandlasten %1 haben kein wall_pressure_pa</translation>
    </message>
    <message>
        <source>none of the wall&apos;s %1 lumen points lies within %2 mm of the blood flow&apos;s wall (%3): the flow ran through other vessels</source>
        <translation>keiner der %1 Lumenpunkte der Wand liegt innerhalb von %2 mm von der Wand der Blutströmung (%3): die Strömung lief durch andere Gefäße</translation>
    </message>
    <message>
        <source>flow_wall_pressure 1 needs a blood-flow run&apos;s wall loads in the study (Flow &gt; Blood Flow, or vascusim-cli simulate sph, run to its averaging window)</source>
        <translation>flow_wall_pressure 1 braucht die Wandlasten eines Blutströmungslaufs in der Studie (Strömung &gt; Blutfluss (SPH) oder vascusim-cli simulate sph, bis in sein Mittelungsfenster gerechnet)</translation>
    </message>
    <message>
        <source>the wall mesh has no wall_layer field: its lumen is not known</source>
        <translation>das Wandnetz hat kein Feld wall_layer: sein Lumen ist unbekannt</translation>
    </message>
    <message>
        <source>the blood flow&apos;s wall pressure reached %1 % of the lumen; the rest carries the uniform pressure</source>
        <translation>der Wanddruck der Blutströmung erreichte %1 % des Lumens; der Rest trägt den gleichförmigen Druck</translation>
    </message>
    <message>
        <source>flow_wall_pressure 1 needs the blood flow&apos;s wall pressure on the wall&apos;s lumen (vascusim-cli simulate fem or the workstation add it from the study&apos;s newest blood-flow run)</source>
        <translation>flow_wall_pressure 1 braucht den Wanddruck der Blutströmung auf dem Lumen der Wand (vascusim-cli simulate fem oder die Workstation fügen ihn aus dem neuesten Blutströmungslauf der Studie hinzu)</translation>
    </message>
    <message>
        <source>flow_wall_pressure 1 needs wall_model 1 (the quadratic hyperelastic wall)</source>
        <translation>flow_wall_pressure 1 braucht wall_model 1 (die quadratische hyperelastische Wand)</translation>
    </message>
    <message>
        <source>the lumen&apos;s added pressure (%1) must be finite and leave the pressure positive (%2 Pa + %3 Pa)</source>
        <translation>der zusätzliche Lumendruck (%1) muss endlich sein und den Druck positiv lassen (%2 Pa + %3 Pa)</translation>
    </message>
    <message>
        <source>%1 face pressures for %2 pressure faces</source>
        <translation>%1 Flächendrücke für %2 Druckflächen</translation>
    </message>
</context>
<context>
    <name>vsim::Parameters</name>
    <message>
        <source>Layer 1: window and region growing</source>
        <translation>Schicht 1: Fenster und Bereichswachstum</translation>
    </message>
    <message>
        <source>Lowest contrast HU</source>
        <translation>Niedrigster Kontrast-HU</translation>
    </message>
    <message>
        <source>Lowest HU of contrast-filled blood; kidneys and tumour blush (about 150 HU) stay below.</source>
        <translation>Niedrigster HU-Wert des kontrastierten Blutes; Nieren und Tumor-Blush (etwa 150 HU) bleiben darunter.</translation>
    </message>
    <message>
        <source>Highest contrast HU</source>
        <translation>Höchster Kontrast-HU</translation>
    </message>
    <message>
        <source>Highest HU of contrast-filled blood; bone and calcium above it are excluded.</source>
        <translation>Höchster HU-Wert des kontrastierten Blutes; Knochen und Kalk darüber werden ausgeschlossen.</translation>
    </message>
    <message>
        <source>Denoising sigma</source>
        <translation>Glättungs-Sigma</translation>
    </message>
    <message>
        <source>Recursive Gaussian applied before thresholding (noise and partial volume).</source>
        <translation>Rekursiver Gauß-Filter vor der Schwelle (Rauschen und Partialvolumen).</translation>
    </message>
    <message>
        <source>Boundary level</source>
        <translation>Randniveau</translation>
    </message>
    <message>
        <source>Boundary HU = tissue + fraction x (blood - tissue); 0.5 is the partial-volume half level.</source>
        <translation>Rand-HU = Gewebe + Anteil x (Blut - Gewebe); 0,5 ist das halbe Niveau des Partialvolumens.</translation>
    </message>
    <message>
        <source>Automatic seed erosion</source>
        <translation>Erosion für den automatischen Saatpunkt</translation>
    </message>
    <message>
        <source>The automatic seed lies in the largest bright component left after eroding this much (thick tubes).</source>
        <translation>Der automatische Saatpunkt liegt in der größten hellen Komponente, die nach einer Erosion um diesen Betrag bleibt (dicke Röhren).</translation>
    </message>
    <message>
        <source>Region margin</source>
        <translation>Bereichsrand</translation>
    </message>
    <message>
        <source>Margin around the vessels found coarsely, inside which the fine layers work.</source>
        <translation>Rand um die grob gefundenen Gefäße, innerhalb dessen die feinen Schichten arbeiten.</translation>
    </message>
    <message>
        <source>Layer 2: vesselness</source>
        <translation>Schicht 2: Vesselness</translation>
    </message>
    <message>
        <source>Vesselness threshold</source>
        <translation>Vesselness-Schwelle</translation>
    </message>
    <message>
        <source>Relative Frangi vesselness above which thin branches are added (0 turns layer 2 off).</source>
        <translation>Relative Frangi-Vesselness, oberhalb derer dünne Äste hinzukommen (0 schaltet Schicht 2 ab).</translation>
    </message>
    <message>
        <source>Smallest vessel scale</source>
        <translation>Kleinste Gefäßskala</translation>
    </message>
    <message>
        <source>Smallest Hessian scale.</source>
        <translation>Kleinste Hesse-Skala.</translation>
    </message>
    <message>
        <source>Largest vessel scale</source>
        <translation>Größte Gefäßskala</translation>
    </message>
    <message>
        <source>Largest Hessian scale.</source>
        <translation>Größte Hesse-Skala.</translation>
    </message>
    <message>
        <source>Vesselness scales</source>
        <translation>Vesselness-Skalen</translation>
    </message>
    <message>
        <source>Number of Hessian scales.</source>
        <translation>Anzahl der Hesse-Skalen.</translation>
    </message>
    <message>
        <source>Layer 3: level set</source>
        <translation>Schicht 3: Level-Set</translation>
    </message>
    <message>
        <source>Level-set steps</source>
        <translation>Level-Set-Schritte</translation>
    </message>
    <message>
        <source>Steps of the threshold level set that moves the boundary onto the boundary level (0 turns layer 3 off).</source>
        <translation>Schritte des Schwellen-Level-Sets, das den Rand auf das Randniveau bewegt (0 schaltet Schicht 3 ab).</translation>
    </message>
    <message>
        <source>Level-set curvature weight</source>
        <translation>Krümmungsgewicht des Level-Sets</translation>
    </message>
    <message>
        <source>Weight of the curvature (smoothing) term against the contrast term; large values shrink thin vessels.</source>
        <translation>Gewicht des Krümmungsterms (Glättung) gegenüber dem Kontrastterm; große Werte lassen dünne Gefäße schrumpfen.</translation>
    </message>
    <message>
        <source>Layer 4: refinement and clean-up</source>
        <translation>Schicht 4: Verfeinerung und Bereinigung</translation>
    </message>
    <message>
        <source>Bone margin</source>
        <translation>Knochenabstand</translation>
    </message>
    <message>
        <source>Voxels this close to bone or calcium (above the highest contrast HU) are removed.</source>
        <translation>Voxel, die so nah an Knochen oder Kalk liegen (über dem höchsten Kontrast-HU), werden entfernt.</translation>
    </message>
    <message>
        <source>Refinement sigma</source>
        <translation>Verfeinerungs-Sigma</translation>
    </message>
    <message>
        <source>Recursive Gaussian refinement of the label boundary (thesis ch. 4.1); 0 turns it off.</source>
        <translation>Rekursive Gauß-Verfeinerung des Label-Randes (Dissertation Kap. 4.1); 0 schaltet sie ab.</translation>
    </message>
    <message>
        <source>Guided segmentation (waves from points)</source>
        <translation>Geführte Segmentierung (Wellen von Punkten)</translation>
    </message>
    <message>
        <source>Wave width</source>
        <translation>Wellenbreite</translation>
    </message>
    <message>
        <source>Path-length width of one wave; its connected pieces are the vessel&apos;s cross-sections.</source>
        <translation>Weglängen-Breite einer Welle; ihre zusammenhängenden Stücke sind die Querschnitte des Gefäßes.</translation>
    </message>
    <message>
        <source>Leak area factor</source>
        <translation>Leck-Flächenfaktor</translation>
    </message>
    <message>
        <source>A cross-section this many times the narrowest of the 12 before it is a leak and is cut back to that neck (explosion control as in Tschirren 2005).</source>
        <translation>Ein Querschnitt, der so viel mal größer ist als der engste der 12 davor, ist ein Leck und wird auf diesen Hals zurückgeschnitten (Explosionskontrolle wie bei Tschirren 2005).</translation>
    </message>
    <message>
        <source>Smallest leak</source>
        <translation>Kleinstes Leck</translation>
    </message>
    <message>
        <source>Cross-sections smaller than this are never called leaks.</source>
        <translation>Kleinere Querschnitte gelten nie als Leck.</translation>
    </message>
    <message>
        <source>Thin vessel</source>
        <translation>Dünnes Gefäß</translation>
    </message>
    <message>
        <source>A front whose cross-section is under this (a vessel under 3.2 mm across) grows on down to the thin level: the scanner&apos;s blur dims a tip under 1 mm below the half level of the blood. 0: off.</source>
        <translation>Eine Front mit kleinerem Querschnitt (ein Gefäß unter 3,2 mm Durchmesser) wächst bis zum Dünn-Niveau weiter: die Unschärfe des Scanners dämpft eine Spitze unter 1 mm unter das halbe Niveau des Blutes. 0: aus.</translation>
    </message>
    <message>
        <source>Thin level</source>
        <translation>Dünn-Niveau</translation>
    </message>
    <message>
        <source>The thin level: this fraction of the way from the tissue to the blood, and at least 4 robust standard deviations of the smoothed tissue above it.</source>
        <translation>Das Dünn-Niveau: dieser Anteil des Weges vom Gewebe zum Blut, und mindestens 4 robuste Standardabweichungen des geglätteten Gewebes darüber.</translation>
    </message>
    <message>
        <source>Aortic branch length</source>
        <translation>Länge der Aortenäste</translation>
    </message>
    <message>
        <source>Target aorta: path length followed into a branch (a cross-section under a quarter of the trunk&apos;s).</source>
        <translation>Ziel Aorta: Weglänge, die in einen Ast verfolgt wird (ein Querschnitt unter einem Viertel des Stammes).</translation>
    </message>
    <message>
        <source>Aortic branches (hepatic)</source>
        <translation>Aortenäste (hepatisch)</translation>
    </message>
    <message>
        <source>Target hepatic: the aortic point&apos;s front (the widest) fills the aorta but enters its branches only this far; the other points&apos; fronts grow the tree and cannot pass the aorta.</source>
        <translation>Ziel hepatisch: die Front des Aortenpunktes (die breiteste) füllt die Aorta, tritt aber nur so weit in ihre Äste ein; die Fronten der anderen Punkte wachsen den Baum und können die Aorta nicht passieren.</translation>
    </message>
    <message>
        <source>Join points by minimal paths</source>
        <translation>Punkte über minimale Pfade verbinden</translation>
    </message>
    <message>
        <source>Target hepatic: a point whose front stopped short of the aorta&apos;s (cut at a touching vein or organ) is joined to it along the minimal path on vesselness, and the path is given its lumen. 0: off.</source>
        <translation>Ziel hepatisch: ein Punkt, dessen Front vor der Aorta stehen blieb (an einer anliegenden Vene oder einem Organ geschnitten), wird entlang des minimalen Pfades auf der Vesselness mit ihr verbunden, und der Pfad erhält sein Lumen. 0: aus.</translation>
    </message>
    <message>
        <source>Organ growing</source>
        <translation>Organwachstum</translation>
    </message>
    <message>
        <source>Intensity window</source>
        <translation>Intensitätsfenster</translation>
    </message>
    <message>
        <source>Half-width of the HU window around the points&apos; median, in robust standard deviations of the HU near them.</source>
        <translation>Halbe Breite des HU-Fensters um den Median der Punkte, in robusten Standardabweichungen der HU in ihrer Nähe.</translation>
    </message>
    <message>
        <source>Opening radius</source>
        <translation>Öffnungsradius</translation>
    </message>
    <message>
        <source>Bridges thinner than twice this to touching organs of the same density are cut.</source>
        <translation>Brücken, dünner als das Doppelte davon, zu anliegenden Organen gleicher Dichte werden getrennt.</translation>
    </message>
    <message>
        <source>Closing radius</source>
        <translation>Schließungsradius</translation>
    </message>
    <message>
        <source>Gaps narrower than twice this inside the organ (small vessels, noise) are taken in.</source>
        <translation>Lücken im Organ, schmaler als das Doppelte davon (kleine Gefäße, Rauschen), werden aufgenommen.</translation>
    </message>
    <message>
        <source>Reach from the points</source>
        <translation>Reichweite von den Punkten</translation>
    </message>
    <message>
        <source>The label stays within a box this far around the points.</source>
        <translation>Das Label bleibt in einem Quader mit diesem Abstand um die Punkte.</translation>
    </message>
    <message>
        <source>Lesion growing</source>
        <translation>Läsionswachstum</translation>
    </message>
    <message>
        <source>Lesion threshold</source>
        <translation>Läsionsschwelle</translation>
    </message>
    <message>
        <source>The lesion&apos;s boundary: this many spreads of the smoothed liver parenchyma (its histogram peak&apos;s full width at half maximum / 2.355) below the peak (hypodense lesions; above it for hyperdense ones), and at least a quarter of the lesion&apos;s contrast.</source>
        <translation>Der Rand der Läsion: so viele Streuungen des geglätteten Leberparenchyms (volle Halbwertsbreite seines Histogrammgipfels / 2,355) unter dem Gipfel (hypodense Läsionen; darüber für hyperdense), und mindestens ein Viertel des Läsionskontrasts.</translation>
    </message>
    <message>
        <source>Smoothing</source>
        <translation>Glättung</translation>
    </message>
    <message>
        <source>Standard deviation of the Gaussian the CT is smoothed with before the threshold.</source>
        <translation>Standardabweichung des Gauß-Filters, mit dem das CT vor der Schwelle geglättet wird.</translation>
    </message>
    <message>
        <source>Bridges thinner than twice this (along vessels, to a neighbouring lesion) are cut.</source>
        <translation>Brücken, dünner als das Doppelte davon (entlang von Gefäßen, zu einer benachbarten Läsion), werden getrennt.</translation>
    </message>
    <message>
        <source>Gaps narrower than twice this (the enhancing rim, vessels through the lesion) are taken in.</source>
        <translation>Lücken, schmaler als das Doppelte davon (der anreichernde Randsaum, Gefäße durch die Läsion), werden aufgenommen.</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>Oberfläche</translation>
    </message>
    <message>
        <source>Smoothing iterations</source>
        <translation>Glättungsiterationen</translation>
    </message>
    <message>
        <source>Windowed-sinc smoothing iterations (Taubin et al. 1996).</source>
        <translation>Iterationen der Windowed-Sinc-Glättung (Taubin et al. 1996).</translation>
    </message>
    <message>
        <source>Smoothing passband</source>
        <translation>Durchlassband der Glättung</translation>
    </message>
    <message>
        <source>Windowed-sinc pass band: lower is smoother.</source>
        <translation>Durchlassband des Windowed-Sinc-Filters: niedriger ist glatter.</translation>
    </message>
    <message>
        <source>Vertex budget</source>
        <translation>Eckpunkt-Budget</translation>
    </message>
    <message>
        <source>Decimate to about this many vertices (thesis: 1,427-2,251 for simulation); 0 keeps every vertex.</source>
        <translation>Auf etwa so viele Eckpunkte dezimieren (Dissertation: 1.427-2.251 für die Simulation); 0 behält alle Eckpunkte.</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <source>Spur length / radius</source>
        <translation>Sporn-Länge / Radius</translation>
    </message>
    <message>
        <source>End branches shorter than this many lumen radii at their junction are spurs of the thinning.</source>
        <translation>Endäste, kürzer als so viele Lumenradien an ihrer Verzweigung, sind Sporne der Ausdünnung.</translation>
    </message>
    <message>
        <source>Shortest end branch</source>
        <translation>Kürzester Endast</translation>
    </message>
    <message>
        <source>End branches shorter than this are spurs.</source>
        <translation>Kürzere Endäste sind Sporne.</translation>
    </message>
    <message>
        <source>Centerlines</source>
        <translation>Mittellinien</translation>
    </message>
    <message>
        <source>Speed exponent</source>
        <translation>Geschwindigkeitsexponent</translation>
    </message>
    <message>
        <source>Fast-marching speed = (distance to the wall / its maximum)^exponent: higher hugs the medial axis.</source>
        <translation>Fast-Marching-Geschwindigkeit = (Abstand zur Wand / sein Maximum)^Exponent: höher folgt enger der Mittelachse.</translation>
    </message>
    <message>
        <source>B-spline knot spacing</source>
        <translation>B-Spline-Knotenabstand</translation>
    </message>
    <message>
        <source>Knot spacing of the least-squares cubic B-spline that smooths each centerline (thesis ch. 4.1).</source>
        <translation>Knotenabstand des kubischen Kleinste-Quadrate-B-Splines, der jede Mittellinie glättet (Dissertation Kap. 4.1).</translation>
    </message>
    <message>
        <source>Sample step</source>
        <translation>Abtastschritt</translation>
    </message>
    <message>
        <source>Spacing of the resampled centerline points.</source>
        <translation>Abstand der neu abgetasteten Mittellinienpunkte.</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <source>Section spacing</source>
        <translation>Schnittabstand</translation>
    </message>
    <message>
        <source>Distance between cross-sections.</source>
        <translation>Abstand zwischen den Querschnitten.</translation>
    </message>
    <message>
        <source>Junction clearance</source>
        <translation>Abstand zur Verzweigung</translation>
    </message>
    <message>
        <source>Sections closer than 1.5 junction radii plus this to a junction, or this to a segment end, are left out of the figures (branches distort them).</source>
        <translation>Schnitte, die näher als 1,5 Verzweigungsradien plus dieser Wert an einer Verzweigung oder näher als dieser Wert an einem Segmentende liegen, bleiben aus den Werten heraus (Äste verfälschen sie).</translation>
    </message>
    <message>
        <source>Wall mesh</source>
        <translation>Wandnetz</translation>
    </message>
    <message>
        <source>Wall thickness</source>
        <translation>Wanddicke</translation>
    </message>
    <message>
        <source>Offset of the lumen surface (one element layer); an assumption, CT does not resolve the wall: 1.5 mm, the uniform AAA wall of Raghavan et al. 2000 (J Vasc Surg 31:760).</source>
        <translation>Versatz der Lumenoberfläche (eine Elementschicht); eine Annahme, das CT löst die Wand nicht auf: 1,5 mm, die gleichmäßige AAA-Wand nach Raghavan et al. 2000 (J Vasc Surg 31:760).</translation>
    </message>
    <message>
        <source>Sets the largest edge (thin vessels get 0.8 of their radius); thesis meshes: 1,427-2,251 vertices.</source>
        <translation>Legt die größte Kante fest (dünne Gefäße erhalten 0,8 ihres Radius); Netze der Dissertation: 1.427-2.251 Eckpunkte.</translation>
    </message>
    <message>
        <source>Thrombus layer</source>
        <translation>Thrombusschicht</translation>
    </message>
    <message>
        <source>1: the AAA sac&apos;s intraluminal thrombus as its own element layer between the lumen and the wall (needs the sac: Vessels &gt; AAA Sac; run with the Raghavan-Vorp wall model). The CLI&apos;s mesh wall --thrombus.</source>
        <translation>1: der intraluminale Thrombus des AAA-Sacks als eigene Elementschicht zwischen Lumen und Wand (braucht den Sack: Gefäße &gt; AAA-Sack; mit dem Wandmodell nach Raghavan-Vorp rechnen). In der CLI: mesh wall --thrombus.</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>Material model</source>
        <translation>Materialmodell</translation>
    </message>
    <message>
        <source>0: co-rotational linear elasticity (thesis), 1: St. Venant-Kirchhoff (Green strain; CPU only).</source>
        <translation>0: korotierte lineare Elastizität (Dissertation), 1: St. Venant-Kirchhoff (Green-Dehnung; nur CPU).</translation>
    </message>
    <message>
        <source>Young&apos;s modulus</source>
        <translation>Elastizitätsmodul</translation>
    </message>
    <message>
        <source>Wall stiffness (thesis patient 1: 4.23 MPa).</source>
        <translation>Wandsteifigkeit (Dissertation, Patient 1: 4,23 MPa).</translation>
    </message>
    <message>
        <source>Poisson&apos;s ratio</source>
        <translation>Querkontraktionszahl</translation>
    </message>
    <message>
        <source>Thesis: 0.23 (printed as 0.23 MPa, a typo).</source>
        <translation>Dissertation: 0,23 (als 0,23 MPa gedruckt, ein Druckfehler).</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>Dichte</translation>
    </message>
    <message>
        <source>Wall density (lumped mass).</source>
        <translation>Wanddichte (konzentrierte Masse).</translation>
    </message>
    <message>
        <source>Integration</source>
        <translation>Integration</translation>
    </message>
    <message>
        <source>Time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <source>Backward Euler step.</source>
        <translation>Schritt des impliziten Euler-Verfahrens.</translation>
    </message>
    <message>
        <source>Rayleigh alpha</source>
        <translation>Rayleigh-Alpha</translation>
    </message>
    <message>
        <source>Mass-proportional damping (thesis: 0).</source>
        <translation>Massenproportionale Dämpfung (Dissertation: 0).</translation>
    </message>
    <message>
        <source>Rayleigh beta</source>
        <translation>Rayleigh-Beta</translation>
    </message>
    <message>
        <source>Stiffness-proportional damping (thesis: 0.22 s).</source>
        <translation>Steifigkeitsproportionale Dämpfung (Dissertation: 0,22 s).</translation>
    </message>
    <message>
        <source>PCG tolerance</source>
        <translation>PCG-Toleranz</translation>
    </message>
    <message>
        <source>Relative residual of the implicit solve.</source>
        <translation>Relatives Residuum der impliziten Lösung.</translation>
    </message>
    <message>
        <source>PCG iterations</source>
        <translation>PCG-Iterationen</translation>
    </message>
    <message>
        <source>Largest number of PCG iterations per step.</source>
        <translation>Höchstzahl der PCG-Iterationen je Schritt.</translation>
    </message>
    <message>
        <source>PCG preconditioner</source>
        <translation>PCG-Vorkonditionierer</translation>
    </message>
    <message>
        <source>0: block Jacobi (the thesis&apos;s; hundreds of iterations to 1e-8 on a wall), 1: smoothed-aggregation multigrid (tens of iterations, each about five products; set up on the host at the first step; CPU and CUDA). With 1, a tolerance of 1e-8 and a cap of a few hundred every step converges.</source>
        <translation>0: Block-Jacobi (wie in der Dissertation; Hunderte Iterationen bis 1e-8 an einer Wand), 1: Smoothed-Aggregation-Mehrgitter (Dutzende Iterationen zu je etwa fünf Produkten; beim ersten Schritt auf dem Host aufgebaut; CPU und CUDA). Mit 1 konvergiert jeder Schritt bei einer Toleranz von 1e-8 und einer Obergrenze von einigen hundert.</translation>
    </message>
    <message>
        <source>Thesis rupture protocol</source>
        <translation>Ruptur-Protokoll der Dissertation</translation>
    </message>
    <message>
        <source>Ramp start</source>
        <translation>Rampenbeginn</translation>
    </message>
    <message>
        <source>Mid-vessel pressure at the start of the ramp.</source>
        <translation>Druck in der Gefäßmitte zu Beginn der Rampe.</translation>
    </message>
    <message>
        <source>Ramp end</source>
        <translation>Rampenende</translation>
    </message>
    <message>
        <source>Mid-vessel pressure at the end of the ramp.</source>
        <translation>Druck in der Gefäßmitte am Ende der Rampe.</translation>
    </message>
    <message>
        <source>Ramp steps</source>
        <translation>Rampenschritte</translation>
    </message>
    <message>
        <source>Time steps of the damped ramp (quasi_static 0).</source>
        <translation>Zeitschritte der gedämpften Rampe (quasi_static 0).</translation>
    </message>
    <message>
        <source>Ramp increment</source>
        <translation>Rampeninkrement</translation>
    </message>
    <message>
        <source>Pressure step between the equilibria of the quasi-static ramp (the onset is then found by bisection to 0.5 % whatever the step).</source>
        <translation>Druckschritt zwischen den Gleichgewichten der quasistatischen Rampe (der Beginn wird dann per Bisektion auf 0,5 % bestimmt, unabhängig vom Schritt).</translation>
    </message>
    <message>
        <source>Loaded length</source>
        <translation>Belastete Länge</translation>
    </message>
    <message>
        <source>Share of the wall&apos;s length (about its middle, along its principal axis) that the pressure acts on.</source>
        <translation>Anteil der Wandlänge (um ihre Mitte, entlang ihrer Hauptachse), auf den der Druck wirkt.</translation>
    </message>
    <message>
        <source>Tear strength</source>
        <translation>Reißfestigkeit</translation>
    </message>
    <message>
        <source>Largest principal stress at which an element tears (the thesis&apos;s tear factor; it does not print a value).</source>
        <translation>Größte Hauptspannung, bei der ein Element reißt (der Reißfaktor der Dissertation; sie nennt keinen Wert).</translation>
    </message>
    <message>
        <source>Quasi-static tearing</source>
        <translation>Quasistatisches Reißen</translation>
    </message>
    <message>
        <source>Fracture entropy end</source>
        <translation>Bruchentropie-Ende</translation>
    </message>
    <message>
        <source>Stop once the fracture entropy passes this (3.9: about 50 torn elements&apos; worth).</source>
        <translation>Anhalten, sobald die Bruchentropie diesen Wert überschreitet (3,9: etwa 50 gerissene Elemente).</translation>
    </message>
    <message>
        <source>Physiological protocol</source>
        <translation>Physiologisches Protokoll</translation>
    </message>
    <message>
        <source>Blood pressure</source>
        <translation>Blutdruck</translation>
    </message>
    <message>
        <source>Systolic pressure on the lumen.</source>
        <translation>Systolischer Druck auf das Lumen.</translation>
    </message>
    <message>
        <source>Wall model</source>
        <translation>Wandmodell</translation>
    </message>
    <message>
        <source>Wall Poisson&apos;s ratio</source>
        <translation>Querkontraktionszahl der Wand</translation>
    </message>
    <message>
        <source>Near incompressibility of the hyperelastic wall: its bulk modulus from the small-strain shear modulus (wall model 1).</source>
        <translation>Nahezu-Inkompressibilität der hyperelastischen Wand: ihr Kompressionsmodul aus dem Schubmodul bei kleinen Dehnungen (Wandmodell 1).</translation>
    </message>
    <message>
        <source>Zero-pressure geometry</source>
        <translation>Geometrie ohne Druck</translation>
    </message>
    <message>
        <source>1: the unloaded geometry is found first (backward displacement, Bols et al. 2013) so that the loaded wall is the imaged one; 0: the imaged (loaded) geometry is taken as unloaded (wall model 1).</source>
        <translation>1: zuerst wird die unbelastete Geometrie bestimmt (Rückwärtsverschiebung, Bols et al. 2013), sodass die belastete Wand die abgebildete ist; 0: die abgebildete (belastete) Geometrie gilt als unbelastet (Wandmodell 1).</translation>
    </message>
    <message>
        <source>Load increments</source>
        <translation>Laststufen</translation>
    </message>
    <message>
        <source>Pressure increments, each solved to equilibrium; one that fails is retried at half the size (wall model 1).</source>
        <translation>Druckstufen, jede bis zum Gleichgewicht gelöst; eine, die scheitert, wird mit halber Größe wiederholt (Wandmodell 1).</translation>
    </message>
    <message>
        <source>Load path time</source>
        <translation>Zeit des Lastpfades</translation>
    </message>
    <message>
        <source>Wall model 0: simulated time of the damped load path: the pressure ramps up over its first quarter (beta = 0.22 s). The figures are those of the static equilibrium solved after it, which does not depend on the path.</source>
        <translation>Wandmodell 0: simulierte Zeit des gedämpften Lastpfades: der Druck steigt im ersten Viertel an (Beta = 0,22 s). Die Werte sind die des danach gelösten statischen Gleichgewichts, das nicht vom Pfad abhängt.</translation>
    </message>
    <message>
        <source>Settling time step</source>
        <translation>Zeitschritt beim Einschwingen</translation>
    </message>
    <message>
        <source>Wall model 0: backward Euler step while settling (the steady state does not depend on it).</source>
        <translation>Wandmodell 0: Schritt des impliziten Euler-Verfahrens beim Einschwingen (der stationäre Zustand hängt nicht davon ab).</translation>
    </message>
    <message>
        <source>Equilibrium tolerance</source>
        <translation>Gleichgewichtstoleranz</translation>
    </message>
    <message>
        <source>The static equilibrium at the pressure is solved (Newton; GMRES with a sparse Cholesky or LU preconditioner) until ||f_int - f_ext|| / ||f_ext|| is below this; the figures are that state&apos;s. 0 (wall model 0 only): the damped path&apos;s last state.</source>
        <translation>Das statische Gleichgewicht beim Druck wird gelöst (Newton; GMRES mit dünnbesetzter Cholesky- oder LU-Vorkonditionierung), bis ||f_int - f_ext|| / ||f_ext|| darunter liegt; die Werte sind die dieses Zustands. 0 (nur Wandmodell 0): der letzte Zustand des gedämpften Pfades.</translation>
    </message>
    <message>
        <source>Patient (wall strength)</source>
        <translation>Patient (Wandfestigkeit)</translation>
    </message>
    <message>
        <source>Female</source>
        <translation>Weiblich</translation>
    </message>
    <message>
        <source>1 female, 0 male (Vande Geest 2006 SEX = +-0.5); -1 not given: no rupture index (never assumed).</source>
        <translation>1 weiblich, 0 männlich (Vande Geest 2006, SEX = +-0,5); -1 nicht angegeben: kein Rupturindex (nie angenommen).</translation>
    </message>
    <message>
        <source>Family history of AAA</source>
        <translation>AAA in der Familienanamnese</translation>
    </message>
    <message>
        <source>1 with, 0 without a family history (HIST = +-0.5); -1 not given: no rupture index (never assumed).</source>
        <translation>1 mit, 0 ohne familiäre Vorgeschichte (HIST = +-0,5); -1 nicht angegeben: kein Rupturindex (nie angenommen).</translation>
    </message>
    <message>
        <source>Thrombus thickness</source>
        <translation>Thrombusdicke</translation>
    </message>
    <message>
        <source>Local intraluminal thrombus thickness (ILT).</source>
        <translation>Lokale Dicke des intraluminalen Thrombus (ILT).</translation>
    </message>
    <message>
        <source>Reference diameter</source>
        <translation>Referenzdurchmesser</translation>
    </message>
    <message>
        <source>Non-aneurysmal aortic diameter for the normalised diameter (NORD); 0: the sac&apos;s neck outer diameter (the patient&apos;s own, from vascusim-cli sac), 20 mm without a sac.</source>
        <translation>Nicht-aneurysmatischer Aortendurchmesser für den normierten Durchmesser (NORD); 0: der äußere Halsdurchmesser des Sacks (der eigene des Patienten, aus vascusim-cli sac), 20 mm ohne Sack.</translation>
    </message>
    <message>
        <source>Injection</source>
        <translation>Injektion</translation>
    </message>
    <message>
        <source>Injection rate</source>
        <translation>Injektionsrate</translation>
    </message>
    <message>
        <source>Volume rate of the injected drug mixture at the catheter tip.</source>
        <translation>Volumenrate des injizierten Wirkstoffgemischs an der Katheterspitze.</translation>
    </message>
    <message>
        <source>Catheter outer diameter</source>
        <translation>Außendurchmesser des Katheters</translation>
    </message>
    <message>
        <source>Outer diameter of the catheter lying from the tree&apos;s root to its tip, 1 Fr = 1/3 mm (microcatheters 1.7-3.0 Fr); blood passes it through the annulus. 0 leaves it out of the flow.</source>
        <translation>Außendurchmesser des Katheters, der von der Wurzel des Baumes bis zu seiner Spitze liegt, 1 Fr = 1/3 mm (Mikrokatheter 1,7-3,0 Fr); das Blut passiert ihn im Ringspalt. 0 lässt ihn aus der Strömung heraus.</translation>
    </message>
    <message>
        <source>Tip snap distance</source>
        <translation>Fangabstand der Spitze</translation>
    </message>
    <message>
        <source>A tip or control point given as a point this near a node is put on the node.</source>
        <translation>Eine Spitze oder ein Kontrollpunkt, als Punkt so nah an einem Knoten angegeben, wird auf den Knoten gesetzt.</translation>
    </message>
    <message>
        <source>Tip reach</source>
        <translation>Reichweite der Spitze</translation>
    </message>
    <message>
        <source>How far a tip or control point given as a point may lie from the vessel tree.</source>
        <translation>Wie weit eine als Punkt angegebene Spitze oder ein Kontrollpunkt vom Gefäßbaum entfernt liegen darf.</translation>
    </message>
    <message>
        <source>Two-phase drug</source>
        <translation>Zweiphasiger Wirkstoff</translation>
    </message>
    <message>
        <source>Void fraction</source>
        <translation>Gasanteil</translation>
    </message>
    <message>
        <source>Gas volume fraction of the injected drug (thesis eq. 6.2, 6.3); the flow is bubbly up to about 0.25.</source>
        <translation>Gas-Volumenanteil des injizierten Wirkstoffs (Dissertation Gl. 6.2, 6.3); bis etwa 0,25 ist die Strömung eine Blasenströmung.</translation>
    </message>
    <message>
        <source>Gas absorption rate</source>
        <translation>Gas-Absorptionsrate</translation>
    </message>
    <message>
        <source>Gas absorption rate of the bubbly regime (thesis ch. 6.1: 5-20 ml/min); with the bubble size it gives the bubble rate.</source>
        <translation>Gas-Absorptionsrate im Blasenregime (Dissertation Kap. 6.1: 5-20 ml/min); mit der Blasengröße ergibt sie die Blasenrate.</translation>
    </message>
    <message>
        <source>Bubble diameter</source>
        <translation>Blasendurchmesser</translation>
    </message>
    <message>
        <source>Bubble diameter of the bubbly regime (thesis ch. 6.1: 1.29-2.05 mm).</source>
        <translation>Blasendurchmesser im Blasenregime (Dissertation Kap. 6.1: 1,29-2,05 mm).</translation>
    </message>
    <message>
        <source>Liquid density</source>
        <translation>Dichte der Flüssigkeit</translation>
    </message>
    <message>
        <source>Density of the liquid phase (plasma: 1,060 kg/m^3).</source>
        <translation>Dichte der flüssigen Phase (Plasma: 1.060 kg/m^3).</translation>
    </message>
    <message>
        <source>Liquid viscosity</source>
        <translation>Viskosität der Flüssigkeit</translation>
    </message>
    <message>
        <source>Dynamic viscosity of the liquid phase at 37 C (plasma: 3.56 mPa s).</source>
        <translation>Dynamische Viskosität der flüssigen Phase bei 37 C (Plasma: 3,56 mPa s).</translation>
    </message>
    <message>
        <source>Gas density</source>
        <translation>Dichte des Gases</translation>
    </message>
    <message>
        <source>Density of the gas phase.</source>
        <translation>Dichte der Gasphase.</translation>
    </message>
    <message>
        <source>Gas viscosity</source>
        <translation>Viskosität des Gases</translation>
    </message>
    <message>
        <source>Dynamic viscosity of the gas phase at 37 C.</source>
        <translation>Dynamische Viskosität der Gasphase bei 37 C.</translation>
    </message>
    <message>
        <source>Blood flow</source>
        <translation>Blutfluss</translation>
    </message>
    <message>
        <source>Blood carries the drug</source>
        <translation>Blut trägt den Wirkstoff</translation>
    </message>
    <message>
        <source>1: arterial blood enters at the tree&apos;s root and carries the injected drug; 0: the injected drug flows alone, as the thesis models it (ch. 6).</source>
        <translation>1: arterielles Blut tritt an der Wurzel des Baumes ein und trägt den injizierten Wirkstoff; 0: der injizierte Wirkstoff fließt allein, wie die Dissertation ihn modelliert (Kap. 6).</translation>
    </message>
    <message>
        <source>Arterial pressure at the root</source>
        <translation>Arterieller Druck an der Wurzel</translation>
    </message>
    <message>
        <source>Mean pressure at the tree&apos;s root, held unless an inflow is given: the hepatic artery&apos;s mean pressure is close to the aorta&apos;s (normal mean arterial pressure 70-105 mmHg).</source>
        <translation>Mitteldruck an der Wurzel des Baumes, gehalten, sofern kein Zufluss angegeben ist: der Mitteldruck der A. hepatica liegt nahe dem der Aorta (normaler arterieller Mitteldruck 70-105 mmHg).</translation>
    </message>
    <message>
        <source>Arterial inflow</source>
        <translation>Arterieller Zufluss</translation>
    </message>
    <message>
        <source>Blood flow into the tree&apos;s root instead of a pressure; 0: the root is held at the arterial pressure. Hepatic arterial flow is about 25 % of the liver&apos;s 100 ml/min per 100 g (Lautt, Hepatic Circulation, 2009): 100-400 ml/min.</source>
        <translation>Blutfluss in die Wurzel des Baumes statt eines Drucks; 0: die Wurzel wird auf dem arteriellen Druck gehalten. Der hepatisch-arterielle Fluss beträgt etwa 25 % der 100 ml/min je 100 g der Leber (Lautt, Hepatic Circulation, 2009): 100-400 ml/min.</translation>
    </message>
    <message>
        <source>Blood viscosity</source>
        <translation>Blutviskosität</translation>
    </message>
    <message>
        <source>Apparent viscosity of whole blood at arterial shear rates (about 3.5 mPa s at a haematocrit of 0.45), taken as Newtonian.</source>
        <translation>Scheinbare Viskosität des Vollblutes bei arteriellen Scherraten (etwa 3,5 mPa s bei einem Hämatokrit von 0,45), als newtonsch angenommen.</translation>
    </message>
    <message>
        <source>Blood density</source>
        <translation>Blutdichte</translation>
    </message>
    <message>
        <source>Density of whole blood (for the Reynolds number).</source>
        <translation>Dichte des Vollblutes (für die Reynolds-Zahl).</translation>
    </message>
    <message>
        <source>Outlets</source>
        <translation>Abflüsse</translation>
    </message>
    <message>
        <source>Outlets&apos; reference flow</source>
        <translation>Referenzfluss der Abflüsse</translation>
    </message>
    <message>
        <source>Flow that all outlets together drain at the reference pressure drop, split by Murray&apos;s law (hepatic artery flow is about 100-400 ml/min).</source>
        <translation>Fluss, den alle Abflüsse zusammen beim Referenz-Druckabfall abführen, nach dem Murray-Gesetz aufgeteilt (der Fluss der A. hepatica beträgt etwa 100-400 ml/min).</translation>
    </message>
    <message>
        <source>Outlets&apos; reference pressure drop</source>
        <translation>Referenz-Druckabfall der Abflüsse</translation>
    </message>
    <message>
        <source>Pressure drop across the vascular bed beyond the outlets at the reference flow.</source>
        <translation>Druckabfall über das Gefäßbett hinter den Abflüssen beim Referenzfluss.</translation>
    </message>
    <message>
        <source>Pressure beyond the outlets</source>
        <translation>Druck hinter den Abflüssen</translation>
    </message>
    <message>
        <source>Pressure at the far end of the terminal resistances (venous side).</source>
        <translation>Druck am fernen Ende der Endwiderstände (venöse Seite).</translation>
    </message>
    <message>
        <source>Targeting</source>
        <translation>Zielsteuerung</translation>
    </message>
    <message>
        <source>Tumour bed resistance factor</source>
        <translation>Widerstandsfaktor des Tumorbetts</translation>
    </message>
    <message>
        <source>Terminal resistance of the tumour&apos;s outlets times this (below 1 for a hypervascular tumour).</source>
        <translation>Endwiderstand der Tumorabflüsse mal diesem Wert (unter 1 für einen hypervaskulären Tumor).</translation>
    </message>
    <message>
        <source>Filling</source>
        <translation>Füllung</translation>
    </message>
    <message>
        <source>Filling steps</source>
        <translation>Füllschritte</translation>
    </message>
    <message>
        <source>Time steps from the start of the injection to the last outlet&apos;s arrival.</source>
        <translation>Zeitschritte vom Beginn der Injektion bis zur Ankunft am letzten Abfluss.</translation>
    </message>
    <message>
        <source>Working angle</source>
        <translation>Arbeitswinkel</translation>
    </message>
    <message>
        <source>Working C-arm angle</source>
        <translation>C-Bogen-Arbeitswinkel</translation>
    </message>
    <message>
        <source>1: the LAO/RAO and cranial/caudal angles that show the path from the root to the tip with the least foreshortening and overlap (WorkingAngle.h); 0: none.</source>
        <translation>1: die LAO/RAO- und kranial/kaudal-Winkel, die den Pfad von der Wurzel zur Spitze mit der geringsten Verkürzung und Überlagerung zeigen (WorkingAngle.h); 0: keiner.</translation>
    </message>
    <message>
        <source>Territories</source>
        <translation>Versorgungsgebiete</translation>
    </message>
    <message>
        <source>Hepatic outlet reach</source>
        <translation>Hepatische Reichweite der Abflüsse</translation>
    </message>
    <message>
        <source>An outlet whose end lies this near the liver feeds liver tissue; the others (gastroduodenal, gastric) feed none.</source>
        <translation>Ein Abfluss, dessen Ende so nah an der Leber liegt, versorgt Lebergewebe; die anderen (gastroduodenal, gastrisch) keines.</translation>
    </message>
    <message>
        <source>Tumour perfusion factor</source>
        <translation>Tumor-Perfusionsfaktor</translation>
    </message>
    <message>
        <source>Arterial perfusion of tumour tissue per volume over the liver&apos;s: a hypervascular HCC draws several times the surrounding liver&apos;s arterial flow (CT perfusion series report about 3-5 times).</source>
        <translation>Arterielle Perfusion des Tumorgewebes je Volumen im Verhältnis zur Leber: ein hypervaskuläres HCC zieht ein Mehrfaches des arteriellen Flusses der umgebenden Leber (CT-Perfusionsserien berichten etwa das 3- bis 5-fache).</translation>
    </message>
    <message>
        <source>Outlets from territories</source>
        <translation>Abflüsse aus den Versorgungsgebieten</translation>
    </message>
    <message>
        <source>1: with a liver label, an outlet&apos;s resistance follows the tissue it feeds; 0: Murray&apos;s law of the terminal radius alone.</source>
        <translation>1: mit einem Leber-Label folgt der Widerstand eines Abflusses dem Gewebe, das er versorgt; 0: allein das Murray-Gesetz des Endradius.</translation>
    </message>
    <message>
        <source>Inlet</source>
        <translation>Einlass</translation>
    </message>
    <message>
        <source>Inlet mean velocity</source>
        <translation>Mittlere Einlassgeschwindigkeit</translation>
    </message>
    <message>
        <source>over the inlet&apos;s section (the end of the largest vessel), parabolic, ramped up from rest</source>
        <translation>über den Einlassquerschnitt (das Ende des größten Gefäßes), parabolisch, aus der Ruhe hochgefahren</translation>
    </message>
    <message>
        <source>Inlet flow rate</source>
        <translation>Einlass-Flussrate</translation>
    </message>
    <message>
        <source>&gt; 0: replaces the mean velocity</source>
        <translation>&gt; 0: ersetzt die mittlere Geschwindigkeit</translation>
    </message>
    <message>
        <source>Outlet pressure</source>
        <translation>Auslassdruck</translation>
    </message>
    <message>
        <source>at every other vessel end (gauge: the pressures reported are relative to it)</source>
        <translation>an jedem anderen Gefäßende (relativ: die berichteten Drücke beziehen sich darauf)</translation>
    </message>
    <message>
        <source>Stenosis figures</source>
        <translation>Stenosewerte</translation>
    </message>
    <message>
        <source>Compare at</source>
        <translation>Vergleich bei</translation>
    </message>
    <message>
        <source>the sections upstream and downstream of the throat the velocity ratios compare with (thesis: 6 mm in the hand, 30 mm in the heart)</source>
        <translation>die Schnitte vor und hinter der Engstelle, mit denen die Geschwindigkeitsverhältnisse vergleichen (Dissertation: 6 mm in der Hand, 30 mm im Herzen)</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Partikel</translation>
    </message>
    <message>
        <source>Particle spacing</source>
        <translation>Partikelabstand</translation>
    </message>
    <message>
        <source>0: a fifth of the inlet&apos;s radius</source>
        <translation>0: ein Fünftel des Einlassradius</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>End time</source>
        <translation>Endzeit</translation>
    </message>
    <message>
        <source>0: twice the inflow&apos;s ramp (two quarter-wave periods of the vessel)</source>
        <translation>0: das Doppelte der Zufluss-Rampe (zwei Viertelwellen-Perioden des Gefäßes)</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <source>frames kept over the run</source>
        <translation>über den Lauf behaltene Bilder</translation>
    </message>
    <message>
        <source>the lattice the particles were seeded on: it sets their mass and the smoothing length</source>
        <translation>das Gitter, auf dem die Partikel gesetzt wurden: es legt ihre Masse und die Glättungslänge fest</translation>
    </message>
    <message>
        <source>Smoothing length</source>
        <translation>Glättungslänge</translation>
    </message>
    <message>
        <source>h as a multiple of the spacing (the support is 2h); at 2 the quartic kernel&apos;s first moment on a lattice is within 0.2 % of the identity (5.7 % at 1.3: sph-kernel), so pressure gradients come out right</source>
        <translation>h als Vielfaches des Abstands (der Träger ist 2h); bei 2 liegt das erste Moment des quartischen Kerns auf einem Gitter innerhalb von 0,2 % der Identität (5,7 % bei 1,3: sph-kernel), sodass Druckgradienten richtig herauskommen</translation>
    </message>
    <message>
        <source>Fluid</source>
        <translation>Fluid</translation>
    </message>
    <message>
        <source>Rest density</source>
        <translation>Ruhedichte</translation>
    </message>
    <message>
        <source>blood 1060 (thesis Table 5.1)</source>
        <translation>Blut 1060 (Dissertation Tabelle 5.1)</translation>
    </message>
    <message>
        <source>Dynamic viscosity</source>
        <translation>Dynamische Viskosität</translation>
    </message>
    <message>
        <source>blood at high shear about 3.5e-3 (thesis: 3.56e-3)</source>
        <translation>Blut bei hoher Scherung etwa 3,5e-3 (Dissertation: 3,56e-3)</translation>
    </message>
    <message>
        <source>the gas share of the mixture particles (thesis Table 5.1: 0.2 at the needle injection) where the input gives none: rest density and viscosity mixed with air&apos;s (1.205 kg/m^3, 1.86e-5 Pa s)</source>
        <translation>der Gasanteil der Gemischpartikel (Dissertation Tabelle 5.1: 0,2 bei der Nadelinjektion), wo die Eingabe keinen angibt: Ruhedichte und Viskosität mit denen der Luft gemischt (1,205 kg/m^3, 1,86e-5 Pa s)</translation>
    </message>
    <message>
        <source>Numerical sound speed</source>
        <translation>Numerische Schallgeschwindigkeit</translation>
    </message>
    <message>
        <source>at least 10 times the largest flow speed keeps the density within about 1 % (Monaghan 1994)</source>
        <translation>mindestens das 10-fache der größten Strömungsgeschwindigkeit hält die Dichte innerhalb von etwa 1 % (Monaghan 1994)</translation>
    </message>
    <message>
        <source>Reference pressure</source>
        <translation>Referenzdruck</translation>
    </message>
    <message>
        <source>the gauge pressure the rest density stands for (blood flow: the outlets&apos; level): the dynamics work on the pressure above it, every pressure reported adds it back, and prescribed pressures are gauge (FluidModel.h)</source>
        <translation>der relative Druck, für den die Ruhedichte steht (Blutfluss: das Niveau der Auslässe): die Dynamik arbeitet mit dem Druck darüber, jeder berichtete Druck addiert ihn wieder, und vorgegebene Drücke sind relativ (FluidModel.h)</translation>
    </message>
    <message>
        <source>Numerics</source>
        <translation>Numerik</translation>
    </message>
    <message>
        <source>Density diffusion</source>
        <translation>Dichtediffusion</translation>
    </message>
    <message>
        <source>delta of the delta-SPH term (Molteni &amp; Colagrossi 2009; 0 switches it off)</source>
        <translation>Delta des Delta-SPH-Terms (Molteni &amp; Colagrossi 2009; 0 schaltet ihn ab)</translation>
    </message>
    <message>
        <source>Courant number</source>
        <translation>Courant-Zahl</translation>
    </message>
    <message>
        <source>the adaptive step&apos;s safety factor</source>
        <translation>der Sicherheitsfaktor des adaptiven Schritts</translation>
    </message>
    <message>
        <source>Gravity x</source>
        <translation>Schwerkraft x</translation>
    </message>
    <message>
        <source>patient frame (LPS)</source>
        <translation>Patientenkoordinaten (LPS)</translation>
    </message>
    <message>
        <source>Gravity y</source>
        <translation>Schwerkraft y</translation>
    </message>
    <message>
        <source>patient frame (LPS): a supine patient&apos;s gravity is +9.81 (posterior)</source>
        <translation>Patientenkoordinaten (LPS): bei einem Patienten in Rückenlage ist die Schwerkraft +9,81 (posterior)</translation>
    </message>
    <message>
        <source>Gravity z</source>
        <translation>Schwerkraft z</translation>
    </message>
    <message>
        <source>simulated time</source>
        <translation>simulierte Zeit</translation>
    </message>
    <message>
        <source>Guards</source>
        <translation>Wächter</translation>
    </message>
    <message>
        <source>Density guard</source>
        <translation>Dichtewächter</translation>
    </message>
    <message>
        <source>the run stops when a fluid particle&apos;s density is further than this from the rest density (relative)</source>
        <translation>der Lauf hält an, wenn die Dichte eines Fluidpartikels weiter als dieser Wert von der Ruhedichte abweicht (relativ)</translation>
    </message>
    <message>
        <source>Escape margin</source>
        <translation>Austrittsrand</translation>
    </message>
    <message>
        <source>the run stops when a particle leaves the particles&apos; starting box grown by this</source>
        <translation>der Lauf hält an, wenn ein Partikel den um diesen Wert vergrößerten Startquader der Partikel verlässt</translation>
    </message>
    <message>
        <source>Reorder every</source>
        <translation>Neu sortieren alle</translation>
    </message>
    <message>
        <source>the particles are sorted by neighbour cell every so many steps</source>
        <translation>die Partikel werden alle so viele Schritte nach Nachbarzellen sortiert</translation>
    </message>
    <message>
        <source>Body force x</source>
        <translation>Volumenkraft x</translation>
    </message>
    <message>
        <source>a driving force per unit mass (a pressure gradient over the density) in a periodic pipe or channel</source>
        <translation>eine antreibende Kraft je Masseneinheit (ein Druckgradient durch die Dichte) in einem periodischen Rohr oder Kanal</translation>
    </message>
    <message>
        <source>Body force y</source>
        <translation>Volumenkraft y</translation>
    </message>
    <message>
        <source>as body_force_x_m_s2</source>
        <translation>wie body_force_x_m_s2</translation>
    </message>
    <message>
        <source>Body force z</source>
        <translation>Volumenkraft z</translation>
    </message>
    <message>
        <source>Body force frequency</source>
        <translation>Frequenz der Volumenkraft</translation>
    </message>
    <message>
        <source>&gt; 0: the body force oscillates as cos(2 pi f t) (Womersley flow); 0: steady</source>
        <translation>&gt; 0: die Volumenkraft schwingt wie cos(2 pi f t) (Womersley-Strömung); 0: stationär</translation>
    </message>
    <message>
        <source>Domain</source>
        <translation>Gebiet</translation>
    </message>
    <message>
        <source>Periodic length x</source>
        <translation>Periodische Länge x</translation>
    </message>
    <message>
        <source>validation channels: &gt; 0 makes the domain [0, L) wrap around along x (0: open)</source>
        <translation>Validierungskanäle: &gt; 0 lässt das Gebiet [0, L) entlang x umlaufen (0: offen)</translation>
    </message>
    <message>
        <source>Periodic length y</source>
        <translation>Periodische Länge y</translation>
    </message>
    <message>
        <source>as periodic_x_mm, along y</source>
        <translation>wie periodic_x_mm, entlang y</translation>
    </message>
    <message>
        <source>Periodic length z</source>
        <translation>Periodische Länge z</translation>
    </message>
    <message>
        <source>as periodic_x_mm, along z</source>
        <translation>wie periodic_x_mm, entlang z</translation>
    </message>
    <message>
        <source>Walls</source>
        <translation>Wände</translation>
    </message>
    <message>
        <source>Free surface</source>
        <translation>Freie Oberfläche</translation>
    </message>
    <message>
        <source>1 for a liquid with a free surface (a tank, a dam break): the walls hold no suction above it; 0 in vessels</source>
        <translation>1 für eine Flüssigkeit mit freier Oberfläche (ein Tank, ein Dammbruch): die Wände halten darüber keinen Sog; 0 in Gefäßen</translation>
    </message>
    <message>
        <source>Tension in the fluid</source>
        <translation>Zug im Fluid</translation>
    </message>
    <message>
        <source>1: a density below the rest density pulls the fluid together (Tait&apos;s negative pressure; vessels, tanks); 0: a liquid that breaks up (a stream falling from a needle, a splash): each particle&apos;s density is held at its rest density or above, its pressure at 0 or above, and the density guard reads compression only</source>
        <translation>1: eine Dichte unter der Ruhedichte zieht das Fluid zusammen (negativer Druck nach Tait; Gefäße, Tanks); 0: eine Flüssigkeit, die aufbricht (ein Strahl aus einer Nadel, ein Spritzer): die Dichte jedes Partikels wird auf der Ruhedichte oder darüber gehalten, sein Druck auf 0 oder darüber, und der Dichtewächter liest nur Kompression</translation>
    </message>
    <message>
        <source>Wall repulsion</source>
        <translation>Wandabstoßung</translation>
    </message>
    <message>
        <source>the walls&apos; Lennard-Jones backstop (thesis ch. 5.4, Monaghan 1994): a wall particle closer than 0.9 spacings pushes a fluid particle away with D ((r0 / r)^12 - (r0 / r)^4) / r, D this times c0^2 (0.01: about the largest flow speed squared); it holds fluid out of walls thinner than the kernel, but empties a throat a few particles across (sph-stenosis at 0.2 mm: area ratio 4.97 against 3.34 without): 0, off</source>
        <translation>die Lennard-Jones-Rückhaltung der Wände (Dissertation Kap. 5.4, Monaghan 1994): ein Wandpartikel, näher als 0,9 Abstände, stößt ein Fluidpartikel mit D ((r0 / r)^12 - (r0 / r)^4) / r ab, D dieser Wert mal c0^2 (0,01: etwa die größte Strömungsgeschwindigkeit zum Quadrat); sie hält Fluid aus Wänden, die dünner als der Kern sind, leert aber eine Engstelle von wenigen Partikeln Breite (sph-stenosis bei 0,2 mm: Flächenverhältnis 4,97 gegenüber 3,34 ohne): 0, aus</translation>
    </message>
    <message>
        <source>Absorption distance</source>
        <translation>Absorptionsabstand</translation>
    </message>
    <message>
        <source>tracer particles (an injected drug) this close to a wall&apos;s surface are absorbed and counted (0: none)</source>
        <translation>Tracerpartikel (ein injizierter Wirkstoff), die so nah an einer Wandoberfläche sind, werden absorbiert und gezählt (0: keine)</translation>
    </message>
    <message>
        <source>Needle</source>
        <translation>Nadel</translation>
    </message>
    <message>
        <source>Needle bore</source>
        <translation>Nadel-Innendurchmesser</translation>
    </message>
    <message>
        <source>the needle&apos;s inner diameter (16 G: 1.19 mm); the particles a third of it unless the spacing is given</source>
        <translation>der Innendurchmesser der Nadel (16 G: 1,19 mm); die Partikel ein Drittel davon, sofern kein Abstand angegeben ist</translation>
    </message>
    <message>
        <source>Generation rate</source>
        <translation>Erzeugungsrate</translation>
    </message>
    <message>
        <source>particles of the run&apos;s spacing a second (thesis Table 5.1: 300)</source>
        <translation>Partikel im Abstand des Laufs je Sekunde (Dissertation Tabelle 5.1: 300)</translation>
    </message>
    <message>
        <source>Collection box</source>
        <translation>Auffangbehälter</translation>
    </message>
    <message>
        <source>Collection box depth</source>
        <translation>Tiefe des Auffangbehälters</translation>
    </message>
    <message>
        <source>its floor below the vessel&apos;s lowest wall</source>
        <translation>sein Boden unter der tiefsten Wand des Gefäßes</translation>
    </message>
    <message>
        <source>Collection box margin</source>
        <translation>Rand des Auffangbehälters</translation>
    </message>
    <message>
        <source>its sides beyond the open ends</source>
        <translation>seine Seiten jenseits der offenen Enden</translation>
    </message>
    <message>
        <source>0: a third of the bore</source>
        <translation>0: ein Drittel des Innendurchmessers</translation>
    </message>
    <message>
        <source>0: twice a free fall from the needle to the box&apos;s floor</source>
        <translation>0: das Doppelte eines freien Falls von der Nadel zum Boden des Behälters</translation>
    </message>
    <message>
        <source>Tissue</source>
        <translation>Gewebe</translation>
    </message>
    <message>
        <source>Thermal diffusivity</source>
        <translation>Temperaturleitfähigkeit</translation>
    </message>
    <message>
        <source>soft tissue about 0.14 mm^2/s (Duck 1990, Physical Properties of Tissue)</source>
        <translation>Weichgewebe etwa 0,14 mm^2/s (Duck 1990, Physical Properties of Tissue)</translation>
    </message>
    <message>
        <source>Cube edge</source>
        <translation>Würfelkante</translation>
    </message>
    <message>
        <source>faces held at body temperature</source>
        <translation>Flächen auf Körpertemperatur gehalten</translation>
    </message>
    <message>
        <source>Cells per edge</source>
        <translation>Zellen je Kante</translation>
    </message>
    <message>
        <source>the grid has cells + 1 nodes per edge</source>
        <translation>das Gitter hat Zellen + 1 Knoten je Kante</translation>
    </message>
    <message>
        <source>Initial rise</source>
        <translation>Anfänglicher Anstieg</translation>
    </message>
    <message>
        <source>peak of the initial temperature rise (the slowest mode)</source>
        <translation>Spitze des anfänglichen Temperaturanstiegs (die langsamste Mode)</translation>
    </message>
    <message>
        <source>the step as a fraction of forward Euler&apos;s stability limit; above 1 the scheme is unstable and the guard stops the run</source>
        <translation>der Schritt als Anteil der Stabilitätsgrenze des expliziten Euler-Verfahrens; über 1 ist das Verfahren instabil und der Wächter hält den Lauf an</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Berechnen</translation>
    </message>
    <message>
        <source>Frame every N steps</source>
        <translation>Ein Bild alle N Schritte</translation>
    </message>
    <message>
        <source>a frame after every N steps (0: not by steps; with both intervals 0, only the first and the last frame)</source>
        <translation>ein Bild nach jeweils N Schritten (0: nicht nach Schritten; sind beide Intervalle 0, nur das erste und das letzte Bild)</translation>
    </message>
    <message>
        <source>Frame every</source>
        <translation>Ein Bild alle</translation>
    </message>
    <message>
        <source>a frame each time the run&apos;s axis (simulated time in s, or pressure in kPa) passes a multiple of this (0: not by the axis)</source>
        <translation>ein Bild jedes Mal, wenn die Achse des Laufs (simulierte Zeit in s oder Druck in kPa) ein Vielfaches dieses Werts überschreitet (0: nicht nach der Achse)</translation>
    </message>
    <message>
        <source>Keep every Nth frame</source>
        <translation>Jedes N-te Bild behalten</translation>
    </message>
    <message>
        <source>keep every Nth frame taken (large runs); the first and the last are always kept, and the run lists which</source>
        <translation>jedes N-te aufgenommene Bild behalten (große Läufe); das erste und das letzte werden immer behalten, und der Lauf listet, welche</translation>
    </message>
    <message>
        <source>Step limit</source>
        <translation>Schrittgrenze</translation>
    </message>
    <message>
        <source>a run that has not reached its end after this many steps stops with a message (a collapsing time step)</source>
        <translation>ein Lauf, der nach so vielen Schritten sein Ende nicht erreicht hat, hält mit einer Meldung an (ein kollabierender Zeitschritt)</translation>
    </message>
    <message>
        <source>Grid</source>
        <translation>Gitter</translation>
    </message>
    <message>
        <source>Cells along the longest edge</source>
        <translation>Zellen entlang der längsten Kante</translation>
    </message>
    <message>
        <source>the grid&apos;s resolution (the thesis demo: 256); cubic cells</source>
        <translation>die Auflösung des Gitters (Demo der Dissertation: 256); würfelförmige Zellen</translation>
    </message>
    <message>
        <source>Longest step</source>
        <translation>Längster Zeitschritt</translation>
    </message>
    <message>
        <source>the step is shorter when the flow is fast (cfl)</source>
        <translation>der Schritt wird kürzer, wenn die Strömung schnell ist (cfl)</translation>
    </message>
    <message>
        <source>cells the fastest flow crosses in one step (semi-Lagrangian advection is stable beyond 1)</source>
        <translation>Zellen, die die schnellste Strömung in einem Schritt durchquert (semi-Lagrange-Advektion ist auch über 1 stabil)</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Velocity advection</source>
        <translation>Advektion der Geschwindigkeit</translation>
    </message>
    <message>
        <source>0 semi-Lagrangian, 1 MacCormack with the limiter (Selle et al. 2008)</source>
        <translation>0 semi-Lagrange, 1 MacCormack mit Begrenzer (Selle et al. 2008)</translation>
    </message>
    <message>
        <source>Projection tolerance</source>
        <translation>Toleranz der Projektion</translation>
    </message>
    <message>
        <source>relative residual of the pressure solve (MGPCG)</source>
        <translation>relatives Residuum der Drucklösung (MGPCG)</translation>
    </message>
    <message>
        <source>Projection iterations</source>
        <translation>Iterationen der Projektion</translation>
    </message>
    <message>
        <source>conjugate-gradient iterations per projection at most</source>
        <translation>höchstens so viele CG-Iterationen je Projektion</translation>
    </message>
    <message>
        <source>Vorticity confinement</source>
        <translation>Wirbelstärkeerhaltung (Vorticity Confinement)</translation>
    </message>
    <message>
        <source>epsilon of Fedkiw et al. 2001 (thesis eq. 7.9): f = epsilon h (N x w)</source>
        <translation>Epsilon nach Fedkiw et al. 2001 (Dissertation Gl. 7.9): f = epsilon h (N x w)</translation>
    </message>
    <message>
        <source>Vortex particle strength</source>
        <translation>Stärke der Wirbelpartikel</translation>
    </message>
    <message>
        <source>epsilon of the particles&apos; forcing (thesis eqs. 7.20-7.23); too large is unstable</source>
        <translation>Epsilon des Antriebs durch die Partikel (Dissertation Gl. 7.20-7.23); zu groß ist instabil</translation>
    </message>
    <message>
        <source>Vortex particle radius</source>
        <translation>Radius der Wirbelpartikel</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Vortex particles</source>
        <translation>Wirbelpartikel</translation>
    </message>
    <message>
        <source>born at the source over its duration (thesis: 1,100 in the demo, 400 in EVH)</source>
        <translation>an der Quelle während ihrer Dauer erzeugt (Dissertation: 1.100 in der Demo, 400 bei EVH)</translation>
    </message>
    <message>
        <source>Smoke emission</source>
        <translation>Rauchemission</translation>
    </message>
    <message>
        <source>particulate mass the cautery releases (an assumption: published rates vary widely)</source>
        <translation>Partikelmasse, die der Kauter freisetzt (eine Annahme: veröffentlichte Raten streuen stark)</translation>
    </message>
    <message>
        <source>Plume temperature</source>
        <translation>Temperatur der Rauchfahne</translation>
    </message>
    <message>
        <source>the plume&apos;s rise above the ambient at the source</source>
        <translation>Übertemperatur der Rauchfahne gegenüber der Umgebung an der Quelle</translation>
    </message>
    <message>
        <source>Plume speed</source>
        <translation>Geschwindigkeit der Rauchfahne</translation>
    </message>
    <message>
        <source>initial velocity of the plume, along gravity&apos;s up (liver ablation: lower, thesis)</source>
        <translation>Anfangsgeschwindigkeit der Rauchfahne, entgegen der Schwerkraft (Leberablation: geringer, Dissertation)</translation>
    </message>
    <message>
        <source>Smoke onset</source>
        <translation>Rauchbeginn</translation>
    </message>
    <message>
        <source>when the smoke starts after the tool&apos;s contact (EVH: 9 s, thesis)</source>
        <translation>wann der Rauch nach dem Kontakt des Instruments beginnt (EVH: 9 s, Dissertation)</translation>
    </message>
    <message>
        <source>Smoke duration</source>
        <translation>Rauchdauer</translation>
    </message>
    <message>
        <source>how long it emits</source>
        <translation>wie lange er austritt</translation>
    </message>
    <message>
        <source>Plume cooling</source>
        <translation>Abkühlung der Rauchfahne</translation>
    </message>
    <message>
        <source>rate at which the plume&apos;s temperature rise relaxes (mixing, walls)</source>
        <translation>Rate, mit der die Übertemperatur der Rauchfahne abklingt (Vermischung, Wände)</translation>
    </message>
    <message>
        <source>Suction</source>
        <translation>Absaugung</translation>
    </message>
    <message>
        <source>Suction on</source>
        <translation>Absaugung ein</translation>
    </message>
    <message>
        <source>when the suction starts</source>
        <translation>wann die Absaugung beginnt</translation>
    </message>
    <message>
        <source>Suction off</source>
        <translation>Absaugung aus</translation>
    </message>
    <message>
        <source>when it stops</source>
        <translation>wann sie endet</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Sicht</translation>
    </message>
    <message>
        <source>Mass extinction coefficient</source>
        <translation>Massenextinktionskoeffizient</translation>
    </message>
    <message>
        <source>Beer-Lambert&apos;s K_m (8.7 m^2/g: Mulholland &amp; Croarkin 2000)</source>
        <translation>K_m nach Beer-Lambert (8,7 m^2/g: Mulholland &amp; Croarkin 2000)</translation>
    </message>
    <message>
        <source>Visibility threshold</source>
        <translation>Sichtbarkeitsschwelle</translation>
    </message>
    <message>
        <source>a pixel is obscured below this transmittance</source>
        <translation>ein Pixel gilt unterhalb dieser Transmission als verdeckt</translation>
    </message>
    <message>
        <source>Obscuration sampling</source>
        <translation>Abtastung der Verdeckung</translation>
    </message>
    <message>
        <source>interval of the obscuration curve</source>
        <translation>Intervall der Verdeckungskurve</translation>
    </message>
    <message>
        <source>the clamped Gaussian&apos;s control radius r, in cells</source>
        <translation>der Wirkradius r der abgeschnittenen Gauß-Funktion, in Zellen</translation>
    </message>
    <message>
        <source>smoke evacuation flow at the suction port (scenes with a port); liver-ablation&apos;s 20 l/min is calibrated to remove 85 % of the smoke in 10 s (Chou 2024) in the box phantom at 64 cells</source>
        <translation>Absaugfluss am Absaugport (Szenen mit Port); die 20 l/min der Leberablation sind so kalibriert, dass im Quader-Phantom mit 64 Zellen 85 % des Rauchs in 10 s entfernt werden (Chou 2024)</translation>
    </message>
    <message>
        <source>1: the wall in static equilibrium at each pressure of the ramp, the tearing onset bracketed by bisection to 0.5 %, one element released per equilibrium (does not depend on the ramp); 0: the thesis&apos;s damped ramp, every element over the limit torn in the same step (the onset lags the ramp).</source>
        <translation>1: die Wand im statischen Gleichgewicht bei jedem Druck der Rampe, der Reißbeginn per Bisektion auf 0,5 % eingegrenzt, ein Element je Gleichgewicht gelöst (unabhängig von der Rampe); 0: die gedämpfte Rampe der Dissertation, jedes Element über der Grenze reißt im selben Schritt (der Beginn hinkt der Rampe nach).</translation>
    </message>
    <message>
        <source>Equilibrium iteration</source>
        <translation>Gleichgewichtsiteration</translation>
    </message>
    <message>
        <source>Quasi-static tearing&apos;s equilibria. 0: full Newton (the pressure&apos;s load stiffness in the tangent, GMRES with a Cholesky preconditioner; CPU). 1: modified Newton without the load stiffness, its symmetric tangent by multigrid conjugate gradients (about 3 times the updates; CPU and CUDA, the same tears on both).</source>
        <translation>Gleichgewichte des quasistatischen Reißens. 0: volles Newton-Verfahren (die Laststeifigkeit des Drucks in der Tangente, GMRES mit Cholesky-Vorkonditionierer; CPU). 1: modifiziertes Newton-Verfahren ohne die Laststeifigkeit, seine symmetrische Tangente per Mehrgitter-konjugierten Gradienten (etwa 3-mal so viele Schritte; CPU und CUDA, auf beiden dieselben Risse).</translation>
    </message>
    <message>
        <source>Particle shifting</source>
        <translation>Partikelverschiebung</translation>
    </message>
    <message>
        <source>A of the shift&apos;s coefficient A h |v| (Lind et al. 2012, Skillen et al. 2013; 0: off): the drift also moves each fluid particle down the gradient of the particles&apos; concentration, which keeps a fast jet&apos;s shear layer from tearing into streaks and voids; vessels only (not with a free surface or without tension)</source>
        <translation>A des Verschiebungskoeffizienten A h |v| (Lind et al. 2012, Skillen et al. 2013; 0: aus): die Drift bewegt jedes Fluidpartikel zusätzlich entlang des Gefälles der Partikelkonzentration, damit die Scherschicht eines schnellen Strahls nicht in Streifen und Lücken zerreißt; nur in Gefäßen (nicht mit freier Oberfläche oder ohne Zugspannung)</translation>
    </message>
    <message>
        <source>Shift correction</source>
        <translation>Verschiebungskorrektur</translation>
    </message>
    <message>
        <source>1: with particle shifting, a shifted particle&apos;s velocity follows it to where the shift moves it, v + dr . grad v (Lind et al. 2012&apos;s Taylor correction); 0: the particle keeps its velocity</source>
        <translation>1: bei Partikelverschiebung folgt die Geschwindigkeit eines verschobenen Partikels ihm an den Ort, an den die Verschiebung es bringt, v + dr . grad v (Taylor-Korrektur nach Lind et al. 2012); 0: das Partikel behält seine Geschwindigkeit</translation>
    </message>
    <message>
        <source>1 (the clinical analysis): quadratic (10-node) tets with the Raghavan &amp; Vorp 2000 hyperelastic AAA wall (nearly incompressible) and the Wang 2001 thrombus where the wall mesh has one, static equilibrium by load increments and Newton&apos;s method (CPU; on 2 cores about 20 s for 15,000 tets, 45 s for 30,000 with a thrombus layer, 85 s for the demo&apos;s 31,000 around a wide sac); 0: the Material group&apos;s law on linear tets, a damped load path then the equilibrium (GPU path possible; linear tets lock in bending and near incompressibility).</source>
        <translation>1 (die klinische Analyse): quadratische (10-Knoten-)Tetraeder mit der hyperelastischen AAA-Wand nach Raghavan &amp; Vorp 2000 (nahezu inkompressibel) und dem Thrombus nach Wang 2001, wo das Wandnetz einen hat, statisches Gleichgewicht in Laststufen mit dem Newton-Verfahren (CPU; auf 2 Kernen etwa 20 s für 15.000 Tetraeder, 45 s für 30.000 mit Thrombusschicht, 85 s für die 31.000 der Demo um einen weiten Sack); 0: das Gesetz der Gruppe Material auf linearen Tetraedern, ein gedämpfter Lastpfad, dann das Gleichgewicht (GPU-Pfad möglich; lineare Tetraeder versteifen bei Biegung und nahezu Inkompressibilität).</translation>
    </message>
    <message>
        <source>Finite Particle Method</source>
        <translation>Finite-Partikel-Methode</translation>
    </message>
    <message>
        <source>1: the density rate from the velocity&apos;s divergence and the density diffusion&apos;s gradient by the first-order Finite Particle Method (thesis eq. 5.17), exact for linear fields where walls or a free surface cut the kernel; 0: the SPH sums</source>
        <translation>1: die Dichteänderung aus der Divergenz der Geschwindigkeit und der Gradient der Dichtediffusion nach der Finite-Partikel-Methode erster Ordnung (Dissertation Gl. 5.17), exakt für lineare Felder, auch wo Wände oder eine freie Oberfläche den Kern abschneiden; 0: die SPH-Summen</translation>
    </message>
    <message>
        <source>Density by summation</source>
        <translation>Dichte durch Summation</translation>
    </message>
    <message>
        <source>1: each fluid particle&apos;s density from how closely its neighbours stand, m_i sum_j W_ij scaled so that the seeding lattice reads the rest density (no continuity equation, so no density diffusion: delta_sph and fpm have nothing to act on); it cannot drift from the particles&apos; spacing, which the continuity density did in a stenotic jet&apos;s wake; vessels only (a fluid that fills its walls); 0: the continuity equation</source>
        <translation>1: die Dichte jedes Fluidpartikels aus dem Abstand seiner Nachbarn, m_i sum_j W_ij, so skaliert, dass das Startgitter die Ruhedichte ergibt (keine Kontinuitätsgleichung, also keine Dichtediffusion: delta_sph und fpm wirken nicht); sie kann nicht vom Abstand der Partikel abdriften, wie es die Kontinuitätsdichte im Nachlauf eines Stenosejets tat; nur für Gefäße (ein Fluid, das seine Wände füllt); 0: die Kontinuitätsgleichung</translation>
    </message>
    <message>
        <source>Density relaxation time</source>
        <translation>Relaxationszeit der Dichte</translation>
    </message>
    <message>
        <source>&gt; 0: with the continuity equation, each fluid particle&apos;s density also relaxes towards its summation density over this time, so that it cannot drift from the particles&apos; spacing over longer times (a stenotic jet&apos;s wake thinned out by 30 % at a constant continuity density) while keeping the continuity density&apos;s smoothness over shorter ones; a drift at rate r leaves the two about r times this apart; vessels only; 0: off</source>
        <translation>&gt; 0: mit der Kontinuitätsgleichung relaxiert die Dichte jedes Fluidpartikels zusätzlich über diese Zeit zu seiner Summationsdichte, sodass sie über längere Zeiten nicht vom Abstand der Partikel abdriften kann (der Nachlauf eines Stenosejets dünnte bei gleichbleibender Kontinuitätsdichte um 30 % aus), über kürzere aber die Glätte der Kontinuitätsdichte behält; eine Drift mit der Rate r lässt beide etwa r mal diese Zeit auseinander; nur für Gefäße; 0: aus</translation>
    </message>
    <message>
        <source>Fluid loss guard</source>
        <translation>Wächter für Fluidverlust</translation>
    </message>
    <message>
        <source>&gt; 0: the run stops when the fluid&apos;s net outflow through the open ends (outflow - inflow, the mass ledger&apos;s) exceeds this share of its first fluid mass: a vessel whose particles thin out while their densities still read full (the continuity density&apos;s drift: density_relaxation_s) empties, and its figures are not a flow&apos;s; 0: off (a domain that fills: an injection)</source>
        <translation>&gt; 0: der Lauf hält an, wenn der Nettoausfluss des Fluids durch die offenen Enden (Ausfluss - Zufluss, laut Massenbilanz) diesen Anteil seiner anfänglichen Fluidmasse übersteigt: ein Gefäß, dessen Partikel ausdünnen, während ihre Dichten noch voll anzeigen (die Drift der Kontinuitätsdichte: density_relaxation_s), leert sich, und seine Werte sind nicht die einer Strömung; 0: aus (ein Gebiet, das sich füllt: eine Injektion)</translation>
    </message>
    <message>
        <source>Shifting speed floor</source>
        <translation>Untergrenze der Verschiebungsgeschwindigkeit</translation>
    </message>
    <message>
        <source>&gt; 0: the shift&apos;s coefficient is A h max(|v|, this), so that slow zones (a stenosis&apos;s separation zone) are shifted too, where with |v| alone the particles clump and leave voids; the flow&apos;s largest speed makes it the delta+-SPH shift (Sun et al. 2017); 0: |v| alone</source>
        <translation>&gt; 0: der Koeffizient der Verschiebung ist A h max(|v|, dieser Wert), damit auch langsame Zonen (die Ablösungszone hinter einer Stenose) verschoben werden, wo die Partikel mit |v| allein verklumpen und Lücken lassen; die größte Geschwindigkeit der Strömung ergibt die Verschiebung von delta+-SPH (Sun et al. 2017); 0: |v| allein</translation>
    </message>
    <message>
        <source>Blood flow&apos;s wall pressure</source>
        <translation>Wanddruck der Blutströmung</translation>
    </message>
    <message>
        <source>1: the lumen carries the blood pressure plus the time-averaged wall pressure of the study&apos;s newest blood-flow run (relative to its outlets; one-way coupling), scaled with the load; 0: a uniform pressure (wall model 1).</source>
        <translation>1: das Lumen trägt den Blutdruck plus den zeitgemittelten Wanddruck des neuesten Blutströmungslaufs der Studie (relativ zu seinen Auslässen; Einweg-Kopplung), mit der Last skaliert; 0: ein gleichförmiger Druck (Wandmodell 1).</translation>
    </message>
</context>
<context>
    <name>vsim::Progress</name>
    <message>
        <source>painting the anatomy</source>
        <translation>Anatomie wird gezeichnet</translation>
    </message>
    <message>
        <source>scanner noise</source>
        <translation>Scannerrauschen</translation>
    </message>
    <message>
        <source>rendering truth labels</source>
        <translation>Referenz-Labels werden gerendert</translation>
    </message>
    <message>
        <source>writing DICOM</source>
        <translation>DICOM wird geschrieben</translation>
    </message>
    <message>
        <source>decoding DICOM</source>
        <translation>DICOM wird dekodiert</translation>
    </message>
    <message>
        <source>DICOM imported</source>
        <translation>DICOM importiert</translation>
    </message>
    <message>
        <source>reading DICOM headers</source>
        <translation>DICOM-Header werden gelesen</translation>
    </message>
    <message>
        <source>phantom written</source>
        <translation>Phantom geschrieben</translation>
    </message>
    <message>
        <source>point-spread function</source>
        <translation>Punktspreizfunktion</translation>
    </message>
    <message>
        <source>resampling</source>
        <translation>Neuabtastung</translation>
    </message>
    <message>
        <source>aortic lumen followed</source>
        <translation>Aortenlumen verfolgt</translation>
    </message>
    <message>
        <source>outer contour</source>
        <translation>Außenkontur</translation>
    </message>
    <message>
        <source>thrombus and wall</source>
        <translation>Thrombus und Wand</translation>
    </message>
    <message>
        <source>perpendicular diameters</source>
        <translation>senkrechte Durchmesser</translation>
    </message>
    <message>
        <source>sac measured</source>
        <translation>Aneurysmasack gemessen</translation>
    </message>
    <message>
        <source>fast marching</source>
        <translation>Fast Marching</translation>
    </message>
    <message>
        <source>minimal paths</source>
        <translation>minimale Pfade</translation>
    </message>
    <message>
        <source>centerlines</source>
        <translation>Mittellinien</translation>
    </message>
    <message>
        <source>segmented</source>
        <translation>segmentiert</translation>
    </message>
    <message>
        <source>liver</source>
        <translation>Leber</translation>
    </message>
    <message>
        <source>smoothing</source>
        <translation>Glättung</translation>
    </message>
    <message>
        <source>growing</source>
        <translation>Wachstum</translation>
    </message>
    <message>
        <source>opening</source>
        <translation>Öffnung</translation>
    </message>
    <message>
        <source>closing</source>
        <translation>Schließung</translation>
    </message>
    <message>
        <source>lesion grown</source>
        <translation>Läsion gewachsen</translation>
    </message>
    <message>
        <source>organ grown</source>
        <translation>Organ gewachsen</translation>
    </message>
    <message>
        <source>partial-volume radii</source>
        <translation>Partialvolumen-Radien</translation>
    </message>
    <message>
        <source>thinning</source>
        <translation>Ausdünnung</translation>
    </message>
    <message>
        <source>pruning</source>
        <translation>Beschneiden</translation>
    </message>
    <message>
        <source>skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <source>measuring</source>
        <translation>Messung</translation>
    </message>
    <message>
        <source>vesselness</source>
        <translation>Gefäßhaftigkeit</translation>
    </message>
    <message>
        <source>finding contrast-filled vessels</source>
        <translation>kontrastierte Gefäße werden gesucht</translation>
    </message>
    <message>
        <source>segmenting vessels</source>
        <translation>Gefäße werden segmentiert</translation>
    </message>
    <message>
        <source>level set</source>
        <translation>Level-Set</translation>
    </message>
    <message>
        <source>clean-up</source>
        <translation>Bereinigung</translation>
    </message>
    <message>
        <source>iso-surface</source>
        <translation>Isofläche</translation>
    </message>
    <message>
        <source>decimating</source>
        <translation>Vereinfachung</translation>
    </message>
    <message>
        <source>surface</source>
        <translation>Oberfläche</translation>
    </message>
    <message>
        <source>damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>quasi-static tearing at %1</source>
        <translation>quasistatisches Einreißen bei %1</translation>
    </message>
    <message>
        <source>lesions and margins</source>
        <translation>Läsionen und Säume</translation>
    </message>
    <message>
        <source>ranking catheter positions by coverage</source>
        <translation>Katheterpositionen werden nach Abdeckung geordnet</translation>
    </message>
    <message>
        <source>flow solved</source>
        <translation>Fluss gelöst</translation>
    </message>
    <message>
        <source>done</source>
        <translation>fertig</translation>
    </message>
    <message>
        <source>ranking catheter positions</source>
        <translation>Katheterpositionen werden geordnet</translation>
    </message>
    <message>
        <source>perfusion territories</source>
        <translation>Perfusionsterritorien</translation>
    </message>
    <message>
        <source>liver voxels</source>
        <translation>Leber-Voxel</translation>
    </message>
    <message>
        <source>working angle</source>
        <translation>Arbeitswinkel</translation>
    </message>
    <message>
        <source>converting to HU</source>
        <translation>Umrechnung in HU</translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation>%1 wird gelesen</translation>
    </message>
    <message>
        <source>read</source>
        <translation>gelesen</translation>
    </message>
    <message>
        <source>vessel ends from the centerlines</source>
        <translation>Gefäßenden aus den Mittellinien</translation>
    </message>
    <message>
        <source>particles from the lumen label</source>
        <translation>Partikel aus dem Lumen-Label</translation>
    </message>
    <message>
        <source>the lumen&apos;s surface for the wall loads</source>
        <translation>Lumenoberfläche für die Wandlasten</translation>
    </message>
    <message>
        <source>demo study written</source>
        <translation>Demo-Studie geschrieben</translation>
    </message>
    <message>
        <source>mask read</source>
        <translation>Maske gelesen</translation>
    </message>
    <message>
        <source>AAA section</source>
        <translation>AAA-Abschnitt</translation>
    </message>
    <message>
        <source>report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <source>lumen surface</source>
        <translation>Lumenoberfläche</translation>
    </message>
    <message>
        <source>remeshing</source>
        <translation>Neuvernetzung</translation>
    </message>
    <message>
        <source>wall</source>
        <translation>Wand</translation>
    </message>
    <message>
        <source>smoke scene</source>
        <translation>Rauchszene</translation>
    </message>
</context>
<context>
    <name>vsim::RunStatus</name>
    <message>
        <source>force residual %1 (tolerance %2)</source>
        <translation>Kraftresiduum %1 (Toleranz %2)</translation>
    </message>
    <message>
        <source>converged</source>
        <translation>konvergiert</translation>
    </message>
    <message>
        <source>converged, %1</source>
        <translation>konvergiert, %1</translation>
    </message>
    <message>
        <source>%1 of %2 solves ended above their tolerance</source>
        <translation>%1 von %2 Lösungen endeten über ihrer Toleranz</translation>
    </message>
    <message>
        <source> at the %1-iteration cap</source>
        <translation> an der Grenze von %1 Iterationen</translation>
    </message>
    <message>
        <source>, worst relative residual %1 (tolerance %2)</source>
        <translation>, schlechtestes relatives Residuum %1 (Toleranz %2)</translation>
    </message>
    <message>
        <source>not converged: %1</source>
        <translation>nicht konvergiert: %1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>stopped by a guard</source>
        <translation>von einer Schutzprüfung gestoppt</translation>
    </message>
    <message>
        <source>stopped by its end condition</source>
        <translation>durch seine Endbedingung beendet</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source> at %1 %2 of %3 %4</source>
        <translation> bei %1 %2 von %3 %4</translation>
    </message>
    <message>
        <source>NOT CONVERGED (%1)</source>
        <translation>NICHT KONVERGIERT (%1)</translation>
    </message>
    <message>
        <source>STOPPED EARLY (%1)</source>
        <translation>VORZEITIG BEENDET (%1)</translation>
    </message>
    <message>
        <source>, %1 of them at the %2-iteration cap</source>
        <translation>, %1 davon an der Grenze von %2 Iterationen</translation>
    </message>
</context>
<context>
    <name>vsim::ViewMeasurement</name>
    <message>
        <source>mean %1 HU, SD %2 HU, area %3 mm2</source>
        <translation>Mittel %1 HU, SD %2 HU, Fläche %3 mm2</translation>
    </message>
    <message>
        <source>straight distance between the two points in the patient frame (mm)</source>
        <translation>gerader Abstand zwischen den beiden Punkten im Patientenkoordinatensystem (mm)</translation>
    </message>
    <message>
        <source>angle at the middle point between the two arms (degrees)</source>
        <translation>Winkel am mittleren Punkt zwischen den beiden Schenkeln (Grad)</translation>
    </message>
    <message>
        <source>CT values (HU) of the voxels nearest the in-plane samples inside the ellipse, one sample per finest voxel spacing squared: mean and sample standard deviation; area of the ellipse, pi a b (mm2)</source>
        <translation>CT-Werte (HU) der Voxel, die den Stichproben in der Ebene innerhalb der Ellipse am nächsten liegen, eine Stichprobe je Quadrat des feinsten Voxelabstands: Mittelwert und Stichproben-Standardabweichung; Fläche der Ellipse, pi a b (mm2)</translation>
    </message>
</context>
<context>
    <name>vsim::app::SegmentNames</name>
    <message>
        <source>unnamed (nodes %1-%2)</source>
        <translation>unbenannt (Knoten %1-%2)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::DicomImportDialog</name>
    <message>
        <source>Import DICOM</source>
        <translation>DICOM importieren</translation>
    </message>
    <message>
        <source>Folder, DICOMDIR or file</source>
        <translation>Ordner, DICOMDIR oder Datei</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Einlesen</translation>
    </message>
    <message>
        <source>Patient / study / series</source>
        <translation>Patient / Studie / Serie</translation>
    </message>
    <message>
        <source>Modality</source>
        <translation>Modalität</translation>
    </message>
    <message>
        <source>Slices</source>
        <translation>Schichten</translation>
    </message>
    <message>
        <source>Voxel spacing (mm)</source>
        <translation>Voxelabstand (mm)</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Warnungen</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>DICOM folder</source>
        <translation>DICOM-Ordner</translation>
    </message>
    <message>
        <source>Reading DICOM headers...</source>
        <translation>DICOM-Header werden gelesen...</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(kein Name)</translation>
    </message>
    <message>
        <source>no ID</source>
        <translation>keine ID</translation>
    </message>
    <message>
        <source>(no description)</source>
        <translation>(keine Beschreibung)</translation>
    </message>
    <message numerus="yes">
        <source>%n file(s), %1 series</source>
        <translation>
            <numerusform>%n Datei, %1 Serien</numerusform>
            <numerusform>%n Dateien, %1 Serien</numerusform>
        </translation>
    </message>
    <message>
        <source> (making previews)</source>
        <translation> (Vorschauen werden erstellt)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::DrugDeliveryPanel</name>
    <message>
        <source>x, y, z mm; empty: the root</source>
        <translation>x, y, z mm; leer: die Wurzel</translation>
    </message>
    <message>
        <source>x, y, z, radius mm; empty: none</source>
        <translation>x, y, z, Radius mm; leer: keiner</translation>
    </message>
    <message>
        <source>x, y, z; ... mm; empty: the first branches</source>
        <translation>x, y, z; ... mm; leer: die ersten Äste</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Pick</source>
        <translation>Wählen</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Berechnen</translation>
    </message>
    <message>
        <source>Catheter tip</source>
        <translation>Katheterspitze</translation>
    </message>
    <message>
        <source>Tumour</source>
        <translation>Tumor</translation>
    </message>
    <message>
        <source>Tumour radius (picked)</source>
        <translation>Tumorradius (gewählt)</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Kontrollpunkte</translation>
    </message>
    <message>
        <source>Outlet</source>
        <translation>Auslass</translation>
    </message>
    <message>
        <source>Drug share (%)</source>
        <translation>Wirkstoffanteil (%)</translation>
    </message>
    <message>
        <source>Arrival (s)</source>
        <translation>Ankunft (s)</translation>
    </message>
    <message>
        <source>Tip pressure %1 mmHg; last outlet reached after %2 s.</source>
        <translation>Druck an der Spitze %1 mmHg; letzter Auslass nach %2 s erreicht.</translation>
    </message>
    <message>
        <source>&lt;br&gt;Control point %1: drug %2 ml/min two-phase, %3 ml/min liquid (%4 % lower)</source>
        <translation>&lt;br&gt;Kontrollpunkt %1: Wirkstoff %2 ml/min zweiphasig, %3 ml/min flüssig (%4 % weniger)</translation>
    </message>
    <message>
        <source>&lt;br&gt;Tumour share %1 % (%2 outlets).</source>
        <translation>&lt;br&gt;Tumoranteil %1 % (%2 Auslässe).</translation>
    </message>
    <message>
        <source>&lt;br&gt;Best tip: node %1 delivers %2 % to the tumour.</source>
        <translation>&lt;br&gt;Beste Spitze: Knoten %1 bringt %2 % in den Tumor.</translation>
    </message>
    <message>
        <source>never</source>
        <translation>nie</translation>
    </message>
    <message>
        <source>DSA-like view at the working angle</source>
        <translation>DSA-ähnliche Ansicht im Arbeitswinkel</translation>
    </message>
    <message>
        <source>Keep this run (the next one is added beside it)</source>
        <translation>Diesen Lauf behalten (der nächste kommt daneben)</translation>
    </message>
    <message>
        <source>The liver as a label: perfusion territories, coverage grade and feeders</source>
        <translation>Die Leber als Label: Perfusionsgebiete, Abdeckungsgrad und Zuflüsse</translation>
    </message>
    <message>
        <source>The tumour as a label (with a liver label): its lesions, margins and coverage</source>
        <translation>Der Tumor als Label (mit einem Leber-Label): seine Läsionen, Ränder und Abdeckung</translation>
    </message>
    <message>
        <source>largest end; or a name, a segment number, or x, y, z mm on it</source>
        <translation>größtes Ende; oder ein Name, eine Segmentnummer oder x, y, z mm darauf</translation>
    </message>
    <message>
        <source>Blood enters through this segment; the tree beyond it is modelled</source>
        <translation>Das Blut tritt durch dieses Segment ein; der Baum dahinter wird modelliert</translation>
    </message>
    <message>
        <source>segment numbers, e.g. 3, 7</source>
        <translation>Segmentnummern, z. B. 3, 7</translation>
    </message>
    <message>
        <source>segment numbers; or untick a feeder below</source>
        <translation>Segmentnummern; oder unten einen Zufluss abwählen</translation>
    </message>
    <message>
        <source>Click a branch of the shown run in the 3D view to add it as a feeder</source>
        <translation>Einen Ast des gezeigten Laufs in der 3D-Ansicht anklicken, um ihn als Zufluss hinzuzufügen</translation>
    </message>
    <message>
        <source>Liver label</source>
        <translation>Leber-Label</translation>
    </message>
    <message>
        <source>Tumour label</source>
        <translation>Tumor-Label</translation>
    </message>
    <message>
        <source>Blood enters at</source>
        <translation>Blut tritt ein bei</translation>
    </message>
    <message>
        <source>Feeders added</source>
        <translation>Hinzugefügte Zuflüsse</translation>
    </message>
    <message>
        <source>Feeders removed</source>
        <translation>Entfernte Zuflüsse</translation>
    </message>
    <message>
        <source>The outlet&apos;s vessel (anatomical name when known)</source>
        <translation>Das Gefäß des Abflusses (anatomischer Name, wenn bekannt)</translation>
    </message>
    <message>
        <source>Share of the injected drug leaving through this outlet (%)</source>
        <translation>Anteil des injizierten Wirkstoffs, der durch diesen Abfluss austritt (%)</translation>
    </message>
    <message>
        <source>Time for the drug front to reach the outlet from the catheter tip (s)</source>
        <translation>Zeit, bis die Wirkstofffront den Abfluss von der Katheterspitze aus erreicht (s)</translation>
    </message>
    <message>
        <source>Feeder (tick: keep)</source>
        <translation>Zufluss (Haken: behalten)</translation>
    </message>
    <message>
        <source>A branch entering the tumour or its margin; untick to remove it from the plan</source>
        <translation>Ein Ast, der in den Tumor oder seinen Rand eintritt; Haken entfernen, um ihn aus dem Plan zu nehmen</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>The feeder&apos;s segment number in the kept tree</source>
        <translation>Die Segmentnummer des Zuflusses im behaltenen Baum</translation>
    </message>
    <message>
        <source>Radius (mm)</source>
        <translation>Radius (mm)</translation>
    </message>
    <message>
        <source>Lumen radius of the feeder (mm)</source>
        <translation>Lumenradius des Zuflusses (mm)</translation>
    </message>
    <message>
        <source>Found</source>
        <translation>Gefunden</translation>
    </message>
    <message>
        <source>Found automatically, or added by hand</source>
        <translation>Automatisch gefunden oder von Hand hinzugefügt</translation>
    </message>
    <message>
        <source>Drug reaches it</source>
        <translation>Wirkstoff erreicht ihn</translation>
    </message>
    <message>
        <source>Whether drug injected at the current tip reaches this feeder</source>
        <translation>Ob der an der aktuellen Spitze injizierte Wirkstoff diesen Zufluss erreicht</translation>
    </message>
    <message>
        <source>The projection as a DSA-like image (the opacified tree, the path to the tip denser)</source>
        <translation>Die Projektion als DSA-ähnliches Bild (der kontrastierte Baum, der Pfad zur Spitze dichter)</translation>
    </message>
    <message>
        <source>added by hand</source>
        <translation>von Hand hinzugefügt</translation>
    </message>
    <message>
        <source>enters lesion + margin</source>
        <translation>tritt in Läsion + Rand ein</translation>
    </message>
    <message>
        <source>feeds the lesion</source>
        <translation>versorgt die Läsion</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keiner)</translation>
    </message>
    <message>
        <source>&lt;br&gt;Blood: %1 ml/min at the root, %2 ml/min reaching the tip (own flow %3); the drug is %4 % of the flow below it; the catheter fills %5 % of the lumen%6.</source>
        <translation>&lt;br&gt;Blut: %1 ml/min an der Wurzel, %2 ml/min erreichen die Spitze (eigener Fluss %3); der Wirkstoff ist %4 % des Flusses darunter; der Katheter füllt %5 % des Lumens%6.</translation>
    </message>
    <message>
        <source>: WEDGED</source>
        <translation>: VERKEILT</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Coverage grade %1&lt;/b&gt;: territory %2 ml (%3 ml of tumour); drug to tumour %4 %, non-tumour liver %5 %, extrahepatic %6 %.</source>
        <translation>&lt;br&gt;&lt;b&gt;Abdeckungsgrad %1&lt;/b&gt;: Versorgungsgebiet %2 ml (%3 ml Tumor); Wirkstoff zum Tumor %4 %, Leber ohne Tumor %5 %, extrahepatisch %6 %.</translation>
    </message>
    <message>
        <source>&lt;br&gt;Lesion %1: %2 mm, %3 mm margin; %4 % covered, margin %5 % (grade %6).</source>
        <translation>&lt;br&gt;Läsion %1: %2 mm, %3 mm Rand; %4 % abgedeckt, Rand %5 % (Grad %6).</translation>
    </message>
    <message>
        <source>%1 (segment %2, %3 mm)</source>
        <translation>%1 (Segment %2, %3 mm)</translation>
    </message>
    <message>
        <source>&lt;br&gt;Feeders: %1.</source>
        <translation>&lt;br&gt;Zuflüsse: %1.</translation>
    </message>
    <message>
        <source>none found</source>
        <translation>keiner gefunden</translation>
    </message>
    <message>
        <source>%1 %2 %</source>
        <translation>%1 %2 %</translation>
    </message>
    <message>
        <source>&lt;br&gt;Drug leaving the liver: %1.</source>
        <translation>&lt;br&gt;Wirkstoff, der die Leber verlässt: %1.</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Working angle %1 %2, %3 %4&lt;/b&gt; (the projection below): the path foreshortened %5 %, overlapped %6 % (from the front: %7 %, %8 %).</source>
        <translation>&lt;br&gt;&lt;b&gt;Arbeitswinkel %1 %2, %3 %4&lt;/b&gt; (die Projektion unten): der Pfad um %5 % verkürzt, zu %6 % überlagert (von vorn: %7 %, %8 %).</translation>
    </message>
    <message>
        <source>LAO</source>
        <translation>LAO</translation>
    </message>
    <message>
        <source>RAO</source>
        <translation>RAO</translation>
    </message>
    <message>
        <source>cranial</source>
        <translation>kranial</translation>
    </message>
    <message>
        <source>caudal</source>
        <translation>kaudal</translation>
    </message>
    <message>
        <source>Drug flow (ml/min; grey: none)</source>
        <translation>Wirkstofffluss (ml/min; grau: keiner)</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
</context>
<context>
    <name>vsim::gui::EndoscopePanel</name>
    <message>
        <source>The centerline segment the camera flies along</source>
        <translation>Das Mittelliniensegment, entlang dessen die Kamera fliegt</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Fly the camera along the segment at the speed set</source>
        <translation>Die Kamera mit der eingestellten Geschwindigkeit entlang des Segments fliegen</translation>
    </message>
    <message>
        <source>Forwards (start to end)</source>
        <translation>Vorwärts (Anfang zum Ende)</translation>
    </message>
    <message>
        <source>Backwards (end to start)</source>
        <translation>Rückwärts (Ende zum Anfang)</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <source>Flight speed along the centerline (mm per second)</source>
        <translation>Fluggeschwindigkeit entlang der Mittellinie (mm je Sekunde)</translation>
    </message>
    <message>
        <source>The camera&apos;s position along the segment (mm from its start)</source>
        <translation>Die Position der Kamera entlang des Segments (mm ab seinem Anfang)</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Focal length of the probe&apos;s lens (mm): longer narrows the field of view (4 mm sensor)</source>
        <translation>Brennweite des Sondenobjektivs (mm): länger verengt das Sichtfeld (4-mm-Sensor)</translation>
    </message>
    <message>
        <source>Distance in focus (mm along the view); out of focus the picture blurs and grows noisy</source>
        <translation>Scharf gestellte Entfernung (mm entlang der Blickrichtung); unscharf wird das Bild verschwommen und verrauscht</translation>
    </message>
    <message>
        <source>Aperture as an f-number: smaller lets in more light and shortens the depth of field</source>
        <translation>Blende als Blendenzahl: kleiner lässt mehr Licht ein und verkürzt die Schärfentiefe</translation>
    </message>
    <message>
        <source>Focus on Centre</source>
        <translation>Auf die Mitte scharf stellen</translation>
    </message>
    <message>
        <source>Set the focus distance to the wall at the picture&apos;s centre</source>
        <translation>Die Schärfeentfernung auf die Wand in der Bildmitte setzen</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>Focal length</source>
        <translation>Brennweite</translation>
    </message>
    <message>
        <source>Focus distance</source>
        <translation>Schärfeentfernung</translation>
    </message>
    <message>
        <source>Aperture (f-number)</source>
        <translation>Blende (Blendenzahl)</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
</context>
<context>
    <name>vsim::gui::FieldTitles</name>
    <message>
        <source>von Mises stress (kPa)</source>
        <translation>Von-Mises-Spannung (kPa)</translation>
    </message>
    <message>
        <source>maximum principal stress (kPa)</source>
        <translation>größte Hauptspannung (kPa)</translation>
    </message>
    <message>
        <source>wall strength (kPa)</source>
        <translation>Wandfestigkeit (kPa)</translation>
    </message>
    <message>
        <source>rupture potential index</source>
        <translation>Rupturpotenzial-Index</translation>
    </message>
    <message>
        <source>material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>displacement (mm)</source>
        <translation>Verschiebung (mm)</translation>
    </message>
    <message>
        <source>displacement x (mm)</source>
        <translation>Verschiebung x (mm)</translation>
    </message>
    <message>
        <source>displacement y (mm)</source>
        <translation>Verschiebung y (mm)</translation>
    </message>
    <message>
        <source>displacement z (mm)</source>
        <translation>Verschiebung z (mm)</translation>
    </message>
    <message>
        <source>drug flow (ml/min)</source>
        <translation>Wirkstofffluss (ml/min)</translation>
    </message>
    <message>
        <source>drug flow, liquid only (ml/min)</source>
        <translation>Wirkstofffluss, nur flüssig (ml/min)</translation>
    </message>
    <message>
        <source>flow (ml/min)</source>
        <translation>Fluss (ml/min)</translation>
    </message>
    <message>
        <source>mean velocity (mm/s)</source>
        <translation>mittlere Geschwindigkeit (mm/s)</translation>
    </message>
    <message>
        <source>pressure at the segment&apos;s start (mmHg)</source>
        <translation>Druck am Anfang des Segments (mmHg)</translation>
    </message>
    <message>
        <source>pressure at the segment&apos;s end (mmHg)</source>
        <translation>Druck am Ende des Segments (mmHg)</translation>
    </message>
    <message>
        <source>Reynolds number</source>
        <translation>Reynolds-Zahl</translation>
    </message>
    <message>
        <source>injected share of the flow (%)</source>
        <translation>injizierter Anteil am Fluss (%)</translation>
    </message>
    <message>
        <source>downstream of the catheter&apos;s tip</source>
        <translation>stromab der Katheterspitze</translation>
    </message>
    <message>
        <source>drug front enters the segment (s)</source>
        <translation>Wirkstofffront erreicht das Segment (s)</translation>
    </message>
    <message>
        <source>drug front leaves the segment (s)</source>
        <translation>Wirkstofffront verlässt das Segment (s)</translation>
    </message>
    <message>
        <source>filled length (mm)</source>
        <translation>gefüllte Länge (mm)</translation>
    </message>
    <message>
        <source>filled fraction</source>
        <translation>gefüllter Anteil</translation>
    </message>
    <message>
        <source>speed (m/s)</source>
        <translation>Geschwindigkeitsbetrag (m/s)</translation>
    </message>
    <message>
        <source>velocity x (m/s)</source>
        <translation>Geschwindigkeit x (m/s)</translation>
    </message>
    <message>
        <source>velocity y (m/s)</source>
        <translation>Geschwindigkeit y (m/s)</translation>
    </message>
    <message>
        <source>velocity z (m/s)</source>
        <translation>Geschwindigkeit z (m/s)</translation>
    </message>
    <message>
        <source>pressure (Pa)</source>
        <translation>Druck (Pa)</translation>
    </message>
    <message>
        <source>density (kg/m³)</source>
        <translation>Dichte (kg/m³)</translation>
    </message>
    <message>
        <source>void fraction</source>
        <translation>Gasanteil</translation>
    </message>
    <message>
        <source>wall particle</source>
        <translation>Wandteilchen</translation>
    </message>
    <message>
        <source>open boundary</source>
        <translation>offener Rand</translation>
    </message>
    <message>
        <source>tracer</source>
        <translation>Tracer</translation>
    </message>
    <message>
        <source>time-averaged wall shear stress (Pa)</source>
        <translation>zeitgemittelte Wandschubspannung (Pa)</translation>
    </message>
    <message>
        <source>oscillatory shear index</source>
        <translation>oszillatorischer Scherindex</translation>
    </message>
    <message>
        <source>wall pressure (Pa)</source>
        <translation>Wanddruck (Pa)</translation>
    </message>
    <message>
        <source>smoke density (mg/m³)</source>
        <translation>Rauchdichte (mg/m³)</translation>
    </message>
    <message>
        <source>temperature rise (K)</source>
        <translation>Temperaturanstieg (K)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::HelpWindow</name>
    <message>
        <source>VascuSim User Guide</source>
        <translation>VascuSim-Benutzerhandbuch</translation>
    </message>
</context>
<context>
    <name>vsim::gui::InteractiveWall</name>
    <message>
        <source>von Mises (kPa)</source>
        <translation>von Mises (kPa)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::MainWindow</name>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;New Study...</source>
        <translation>&amp;Neue Studie...</translation>
    </message>
    <message>
        <source>Study folder (*.vsim)</source>
        <translation>Studienordner (*.vsim)</translation>
    </message>
    <message>
        <source>&amp;Open Study...</source>
        <translation>Studie ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>Import &amp;DICOM...</source>
        <translation>&amp;DICOM importieren...</translation>
    </message>
    <message>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <source>&amp;Import Volume...</source>
        <translation>Volumen &amp;importieren...</translation>
    </message>
    <message>
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <source>Import &amp;Label...</source>
        <translation>&amp;Label importieren...</translation>
    </message>
    <message>
        <source>Import label (a mask on the CT&apos;s grid)</source>
        <translation>Label importieren (eine Maske auf dem Raster des CT)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <source>Export &amp;Report...</source>
        <translation>&amp;Bericht exportieren...</translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <source>&amp;Close Window</source>
        <translation>Fenster &amp;schließen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>Re&amp;name Artifact...</source>
        <translation>Artefakt &amp;umbenennen...</translation>
    </message>
    <message>
        <source>Rename artifact</source>
        <translation>Artefakt umbenennen</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>&amp;Delete Artifact</source>
        <translation>Artefakt &amp;löschen</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Window/Level: &amp;CTA</source>
        <translation>Fenster: &amp;CTA</translation>
    </message>
    <message>
        <source>Window/Level: &amp;Soft Tissue</source>
        <translation>Fenster: &amp;Weichteil</translation>
    </message>
    <message>
        <source>Window/Level: &amp;Bone</source>
        <translation>Fenster: &amp;Knochen</translation>
    </message>
    <message>
        <source>3D: &amp;Anterior View</source>
        <translation>3D: &amp;Ansicht von vorn</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About VascuSim</source>
        <translation>Ü&amp;ber VascuSim</translation>
    </message>
    <message>
        <source>About VascuSim</source>
        <translation>Über VascuSim</translation>
    </message>
    <message>
        <source>&lt;h3&gt;VascuSim&lt;/h3&gt;&lt;p&gt;Patient-specific physics for vascular procedure planning.&lt;/p&gt;&lt;p&gt;Results support planning and need clinical judgement.&lt;/p&gt;&lt;table&gt;%1&lt;/table&gt;</source>
        <translation>&lt;h3&gt;VascuSim&lt;/h3&gt;&lt;p&gt;Patientenspezifische Physik für die Planung vaskulärer Eingriffe.&lt;/p&gt;&lt;p&gt;Die Ergebnisse unterstützen die Planung und erfordern ärztliches Urteil.&lt;/p&gt;&lt;table&gt;%1&lt;/table&gt;</translation>
    </message>
    <message>
        <source>%1: cancelled, nothing changed</source>
        <translation>%1: abgebrochen, nichts geändert</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1: fertig</translation>
    </message>
    <message>
        <source>Artifact</source>
        <translation>Artefakt</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Study</source>
        <translation>Studie</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <source>Workflow</source>
        <translation>Arbeitsablauf</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>No study</source>
        <translation>Keine Studie</translation>
    </message>
    <message>
        <source>%1[*] - VascuSim</source>
        <translation>%1[*] - VascuSim</translation>
    </message>
    <message>
        <source>%1 (read-only) - VascuSim</source>
        <translation>%1 (schreibgeschützt) - VascuSim</translation>
    </message>
    <message>
        <source>damaged</source>
        <translation>beschädigt</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, made by &quot;%2&quot; on %3</source>
        <translation>%1, erzeugt von &quot;%2&quot; am %3</translation>
    </message>
    <message>
        <source>%1 failed</source>
        <translation>%1 fehlgeschlagen</translation>
    </message>
    <message>
        <source>Opened read-only: the study is being written by %1</source>
        <translation>Schreibgeschützt geöffnet: die Studie wird von %1 geschrieben</translation>
    </message>
    <message>
        <source>Study in use</source>
        <translation>Studie in Gebrauch</translation>
    </message>
    <message>
        <source>The study is being written by %1.
Open it read-only, or break the lock if you are sure that program no longer runs.</source>
        <translation>Die Studie wird von %1 geschrieben.
Schreibgeschützt öffnen, oder die Sperre aufheben, wenn Sie sicher sind, dass dieses Programm nicht mehr läuft.</translation>
    </message>
    <message>
        <source>Open Read-Only</source>
        <translation>Schreibgeschützt öffnen</translation>
    </message>
    <message>
        <source>Break the Lock...</source>
        <translation>Sperre aufheben...</translation>
    </message>
    <message>
        <source>Break the lock</source>
        <translation>Sperre aufheben</translation>
    </message>
    <message>
        <source>If %1 still runs, both programs will write the study and results can be lost. Break the lock?</source>
        <translation>Wenn %1 noch läuft, schreiben beide Programme die Studie, und Ergebnisse können verloren gehen. Sperre aufheben?</translation>
    </message>
    <message>
        <source>Open study</source>
        <translation>Studie öffnen</translation>
    </message>
    <message>
        <source>Study opened with problems</source>
        <translation>Studie mit Problemen geöffnet</translation>
    </message>
    <message>
        <source>New study</source>
        <translation>Neue Studie</translation>
    </message>
    <message>
        <source>Import volume</source>
        <translation>Volumen importieren</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Import label</source>
        <translation>Label importieren</translation>
    </message>
    <message>
        <source>The study has no CT image for the label&apos;s grid: import the CT first.</source>
        <translation>Die Studie hat kein CT-Bild für das Raster des Labels: zuerst das CT importieren.</translation>
    </message>
    <message>
        <source>Not Hounsfield units</source>
        <translation>Keine Hounsfield-Einheiten</translation>
    </message>
    <message>
        <source>%1

Rescale to HU (HU = slope x stored value + intercept):</source>
        <translation>%1

Umrechnung in HU (HU = Steigung x gespeicherter Wert + Achsenabschnitt):</translation>
    </message>
    <message>
        <source>Import DICOM</source>
        <translation>DICOM importieren</translation>
    </message>
    <message>
        <source>Save study</source>
        <translation>Studie speichern</translation>
    </message>
    <message>
        <source>Save study as</source>
        <translation>Studie speichern unter</translation>
    </message>
    <message>
        <source>Show image</source>
        <translation>Bild anzeigen</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>Save the changes to this study before closing?</source>
        <translation>Änderungen an dieser Studie vor dem Schließen speichern?</translation>
    </message>
    <message>
        <source>Length (mm)</source>
        <translation>Länge (mm)</translation>
    </message>
    <message>
        <source>Start r (mm)</source>
        <translation>Anfangs-r (mm)</translation>
    </message>
    <message>
        <source>End r (mm)</source>
        <translation>End-r (mm)</translation>
    </message>
    <message>
        <source>Segment</source>
        <comment>a vessel segment (noun)</comment>
        <translation>Segment</translation>
    </message>
    <message>
        <source>Reference Ø (mm)</source>
        <translation>Referenz-Ø (mm)</translation>
    </message>
    <message>
        <source>Minimal Ø (mm)</source>
        <translation>Minimaler Ø (mm)</translation>
    </message>
    <message>
        <source>Stenosis (%)</source>
        <translation>Stenose (%)</translation>
    </message>
    <message>
        <source>Max Ø (mm)</source>
        <translation>Max. Ø (mm)</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <source>V&amp;essels</source>
        <translation>&amp;Gefäße</translation>
    </message>
    <message>
        <source>&amp;Segment Vessels</source>
        <translation>Gefäße &amp;segmentieren</translation>
    </message>
    <message>
        <source>Segment from the &amp;Cursor</source>
        <translation>Ab dem &amp;Cursor segmentieren</translation>
    </message>
    <message>
        <source>S&amp;keleton and Centerlines</source>
        <translation>S&amp;kelett und Mittellinien</translation>
    </message>
    <message>
        <source>&amp;Edit Label (Brush)</source>
        <translation>Label &amp;bearbeiten (Pinsel)</translation>
    </message>
    <message>
        <source>&amp;Parameters...</source>
        <translation>&amp;Parameter...</translation>
    </message>
    <message>
        <source>Vessel parameters</source>
        <translation>Gefäßparameter</translation>
    </message>
    <message>
        <source>Segmentation</source>
        <translation>Segmentierung</translation>
    </message>
    <message>
        <source>Segment vessels</source>
        <translation>Gefäße segmentieren</translation>
    </message>
    <message>
        <source>The study has no CT image: import one first.</source>
        <translation>Die Studie enthält kein CT-Bild: zuerst eines importieren.</translation>
    </message>
    <message>
        <source>Skeleton and centerlines</source>
        <translation>Skelett und Mittellinien</translation>
    </message>
    <message>
        <source>Label Editing</source>
        <translation>Label-Bearbeitung</translation>
    </message>
    <message>
        <source>Paint</source>
        <translation>Malen</translation>
    </message>
    <message>
        <source>Erase</source>
        <translation>Radieren</translation>
    </message>
    <message>
        <source>Paint vessel voxels with the left button in any MPR view (one undo step per stroke)</source>
        <translation>Gefäßvoxel mit der linken Maustaste in einer MPR-Ansicht malen (ein Rückgängig-Schritt pro Strich)</translation>
    </message>
    <message>
        <source>Erase vessel voxels with the left button in any MPR view</source>
        <translation>Gefäßvoxel mit der linken Maustaste in einer MPR-Ansicht radieren</translation>
    </message>
    <message>
        <source> Radius </source>
        <translation> Radius </translation>
    </message>
    <message>
        <source>Apply Edits</source>
        <translation>Änderungen übernehmen</translation>
    </message>
    <message>
        <source>Discard Edits</source>
        <translation>Änderungen verwerfen</translation>
    </message>
    <message>
        <source>Add the edited label to the study as a new artifact (the original stays)</source>
        <translation>Das bearbeitete Label als neues Artefakt zur Studie hinzufügen (das Original bleibt)</translation>
    </message>
    <message>
        <source>Label edits: %1 voxels painted, %2 erased</source>
        <translation>Label-Änderungen: %1 Voxel gemalt, %2 radiert</translation>
    </message>
    <message>
        <source>The study has no vessel label: segment the vessels first.</source>
        <translation>Die Studie enthält keine Gefäßmaske: zuerst die Gefäße segmentieren.</translation>
    </message>
    <message>
        <source>Edit label</source>
        <translation>Label bearbeiten</translation>
    </message>
    <message>
        <source>Apply label edits</source>
        <translation>Label-Änderungen übernehmen</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <source>Centerlines</source>
        <translation>Mittellinien</translation>
    </message>
    <message>
        <source>&amp;Wall</source>
        <translation>&amp;Wand</translation>
    </message>
    <message>
        <source>Build &amp;Wall Mesh</source>
        <translation>&amp;Wandnetz erzeugen</translation>
    </message>
    <message>
        <source>Wall Stress at &amp;Blood Pressure</source>
        <translation>Wandspannung bei &amp;Blutdruck</translation>
    </message>
    <message>
        <source>&amp;Interactive Protocol</source>
        <translation>&amp;Interaktives Protokoll</translation>
    </message>
    <message>
        <source>Wall &amp;Parameters...</source>
        <translation>Wand-&amp;Parameter...</translation>
    </message>
    <message>
        <source>Wall parameters</source>
        <translation>Wandparameter</translation>
    </message>
    <message>
        <source>Wall mesh</source>
        <translation>Wandnetz</translation>
    </message>
    <message>
        <source>Wall mechanics</source>
        <translation>Wandmechanik</translation>
    </message>
    <message>
        <source>The wall needs a vessel label and centerlines: run Segment and Skeleton &amp;&amp; Centerlines first.</source>
        <translation>Die Wand braucht ein Gefäßlabel und Mittellinien: zuerst Segmentieren und Skelett &amp;&amp; Mittellinien ausführen.</translation>
    </message>
    <message>
        <source>Wall: %1 elements, smallest dihedral angle %2 deg</source>
        <translation>Wand: %1 Elemente, kleinster Diederwinkel %2 Grad</translation>
    </message>
    <message>
        <source>Build the wall mesh first (Wall &gt; Build Wall Mesh).</source>
        <translation>Zuerst das Wandnetz erzeugen (Wand &gt; Wandnetz erzeugen).</translation>
    </message>
    <message>
        <source>Wall stress</source>
        <translation>Wandspannung</translation>
    </message>
    <message>
        <source>Thesis rupture protocol</source>
        <translation>Ruptur-Protokoll der Dissertation</translation>
    </message>
    <message>
        <source>Read these results with care: %1</source>
        <translation>Diese Ergebnisse mit Vorsicht lesen: %1</translation>
    </message>
    <message>
        <source>von Mises (kPa), NOT CONVERGED</source>
        <translation>von Mises (kPa), NICHT KONVERGIERT</translation>
    </message>
    <message>
        <source>von Mises (kPa), STOPPED EARLY</source>
        <translation>von Mises (kPa), VORZEITIG BEENDET</translation>
    </message>
    <message>
        <source>von Mises (kPa)</source>
        <translation>von Mises (kPa)</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>0 mmHg</source>
        <translation>0 mmHg</translation>
    </message>
    <message>
        <source>Tear at %1 MPa</source>
        <translation>Reißen bei %1 MPa</translation>
    </message>
    <message>
        <source>Pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <source>Drag the wall with the left button in the 3D view.</source>
        <translation>Die Wand in der 3D-Ansicht mit der linken Maustaste ziehen.</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>%1 mmHg</source>
        <translation>%1 mmHg</translation>
    </message>
    <message>
        <source>%1 frames/s, peak von Mises %2 kPa</source>
        <translation>%1 Bilder/s, höchste von-Mises-Spannung %2 kPa</translation>
    </message>
    <message>
        <source>The simulation paused: %1</source>
        <translation>Die Simulation hält an: %1</translation>
    </message>
    <message>
        <source>Interactive Wall</source>
        <translation>Interaktive Wand</translation>
    </message>
    <message>
        <source>&amp;Drug</source>
        <translation>Wirk&amp;stoff</translation>
    </message>
    <message>
        <source>Drug &amp;Delivery</source>
        <translation>Wirkstoff&amp;gabe</translation>
    </message>
    <message>
        <source>Drug &amp;Parameters...</source>
        <translation>Wirkstoff&amp;parameter...</translation>
    </message>
    <message>
        <source>Drug delivery parameters</source>
        <translation>Parameter der Wirkstoffgabe</translation>
    </message>
    <message>
        <source>Drug delivery</source>
        <translation>Wirkstoffgabe</translation>
    </message>
    <message>
        <source>The network needs centerlines: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>Das Netzwerk braucht Mittellinien: zuerst Skelett &amp;&amp; Mittellinien ausführen.</translation>
    </message>
    <message>
        <source>The tip needs three numbers (mm) and the tumour four (centre and radius).</source>
        <translation>Die Spitze braucht drei Zahlen (mm), der Tumor vier (Mitte und Radius).</translation>
    </message>
    <message>
        <source>The tumour&apos;s radius must be positive.</source>
        <translation>Der Radius des Tumors muss positiv sein.</translation>
    </message>
    <message>
        <source>Control points are x, y, z in mm, separated by &apos;;&apos;.</source>
        <translation>Kontrollpunkte sind x, y, z in mm, getrennt durch &apos;;&apos;.</translation>
    </message>
    <message>
        <source>Drug flow</source>
        <translation>Wirkstofffluss</translation>
    </message>
    <message>
        <source>Drug Delivery</source>
        <translation>Wirkstoffgabe</translation>
    </message>
    <message>
        <source>Drug delivery: %1 outlets, last reached after %2 s</source>
        <translation>Wirkstoffgabe: %1 Auslässe, der letzte nach %2 s erreicht</translation>
    </message>
    <message>
        <source>No PDF viewer opened %1.</source>
        <translation>Kein PDF-Betrachter hat %1 geöffnet.</translation>
    </message>
    <message>
        <source>Replace files</source>
        <translation>Dateien ersetzen</translation>
    </message>
    <message>
        <source>These files exist already:
%1
Replace them?</source>
        <translation>Diese Dateien gibt es schon:
%1
Ersetzen?</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>Bericht geschrieben nach %1</translation>
    </message>
    <message>
        <source>Preparing the views</source>
        <translation>Ansichten werden vorbereitet</translation>
    </message>
    <message>
        <source>A step is running: wait for it or cancel it</source>
        <translation>Ein Schritt läuft: warten oder abbrechen</translation>
    </message>
    <message>
        <source>Open or create a study first (File menu)</source>
        <translation>Zuerst eine Studie öffnen oder anlegen (Menü Datei)</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>image</source>
        <translation>Bild</translation>
    </message>
    <message>
        <source>label</source>
        <translation>Label</translation>
    </message>
    <message>
        <source>surface</source>
        <translation>Oberfläche</translation>
    </message>
    <message>
        <source>volume mesh</source>
        <translation>Volumennetz</translation>
    </message>
    <message>
        <source>skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <source>network</source>
        <translation>Netzwerk</translation>
    </message>
    <message>
        <source>report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <source>run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>measurement</source>
        <translation>Messung</translation>
    </message>
    <message>
        <source>Sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>3D brush: paint or erase a ball of the radius through the slices, not a disc in the view&apos;s plane</source>
        <translation>3D-Pinsel: eine Kugel des Radius durch die Schichten malen oder radieren, keine Scheibe in der Ebene der Ansicht</translation>
    </message>
    <message>
        <source> Paint as </source>
        <translation> Malen als </translation>
    </message>
    <message>
        <source>Lumen</source>
        <translation>Lumen</translation>
    </message>
    <message>
        <source>Thrombus</source>
        <translation>Thrombus</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Wand</translation>
    </message>
    <message>
        <source>The label value the brush paints: the lumen, or the thrombus and wall of an AAA sac label</source>
        <translation>Der Label-Wert, den der Pinsel malt: das Lumen, oder Thrombus und Wand eines AAA-Sack-Labels</translation>
    </message>
    <message>
        <source>Remove Island</source>
        <translation>Insel entfernen</translation>
    </message>
    <message>
        <source>Remove the connected piece of the label at the cursor (click it in an MPR view first)</source>
        <translation>Das zusammenhängende Stück des Labels am Cursor entfernen (zuerst in einer MPR-Ansicht anklicken)</translation>
    </message>
    <message>
        <source>No labelled voxel within 3 mm of the cursor</source>
        <translation>Kein Label-Voxel innerhalb von 3 mm um den Cursor</translation>
    </message>
    <message>
        <source>Island removed: %1 voxels erased in all</source>
        <translation>Insel entfernt: insgesamt %1 Voxel radiert</translation>
    </message>
    <message>
        <source>Volumes (*.nii *.nii.gz *.nrrd *.nhdr *.mha *.mhd);;DICOM SEG or a mask series&apos; slice (*.dcm *.DCM *.IMA);;All files (*)</source>
        <translation>Volumen (*.nii *.nii.gz *.nrrd *.nhdr *.mha *.mhd);;DICOM SEG oder eine Schicht einer Maskenserie (*.dcm *.DCM *.IMA);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Window/Level: &amp;Lung</source>
        <translation>Fenster/Level: &amp;Lunge</translation>
    </message>
    <message>
        <source>&amp;Reset Slice Views</source>
        <translation>Schnittansichten &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Centre the volume and show it whole in the axial, coronal and sagittal views (R in a view)</source>
        <translation>Das Volumen zentrieren und ganz in der axialen, koronalen und sagittalen Ansicht zeigen (R in einer Ansicht)</translation>
    </message>
    <message>
        <source>&amp;Link Slice Views</source>
        <translation>Schnittansichten &amp;koppeln</translation>
    </message>
    <message>
        <source>Linked, the slice views share the cursor and window/level</source>
        <translation>Gekoppelt teilen die Schnittansichten Cursor und Fenster/Level</translation>
    </message>
    <message>
        <source>Show &amp;Crosshair</source>
        <translation>&amp;Fadenkreuz zeigen</translation>
    </message>
    <message>
        <source>Right Drag &amp;Zooms (Slicer)</source>
        <translation>Rechts ziehen &amp;zoomt (Slicer)</translation>
    </message>
    <message>
        <source>Right drag in a slice view zooms instead of changing window/level (kept in the settings)</source>
        <translation>Ziehen mit der rechten Taste in einer Schnittansicht zoomt, statt Fenster/Level zu ändern (in den Einstellungen gespeichert)</translation>
    </message>
    <message>
        <source>Thick Slab &amp;MIP</source>
        <translation>Dicke Schicht (&amp;MIP)</translation>
    </message>
    <message>
        <source>Off (thin slice)</source>
        <translation>Aus (dünne Schicht)</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>&amp;Keyboard and Mouse</source>
        <translation>&amp;Tastatur und Maus</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>System Language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <source>The language changes when VascuSim starts next.</source>
        <translation>Die Sprache wechselt beim nächsten Start von VascuSim.</translation>
    </message>
    <message>
        <source>&amp;Liver from Points</source>
        <translation>&amp;Leber aus Punkten</translation>
    </message>
    <message>
        <source>&amp;Tumour from Points</source>
        <translation>&amp;Tumor aus Punkten</translation>
    </message>
    <message>
        <source>The tumour label is read with a liver label: choose the liver too.</source>
        <translation>Das Tumor-Label wird mit einem Leber-Label gelesen: auch die Leber wählen.</translation>
    </message>
    <message>
        <source>Feeders are corrected on a run with a liver label: choose the liver too.</source>
        <translation>Zuflüsse werden an einem Lauf mit Leber-Label korrigiert: auch die Leber wählen.</translation>
    </message>
    <message>
        <source>Tumour from points</source>
        <translation>Tumor aus Punkten</translation>
    </message>
    <message>
        <source>Liver from points</source>
        <translation>Leber aus Punkten</translation>
    </message>
    <message>
        <source>Place include points inside the %1 first (Vessels &gt; Segment from Points, on the MPR views), then grow it from them.</source>
        <translation>Zuerst Einschlusspunkte in %1 setzen (Gefäße &gt; Aus Punkten segmentieren, in den MPR-Ansichten), dann daraus wachsen lassen.</translation>
    </message>
    <message>
        <source>tumour</source>
        <translation>den Tumor</translation>
    </message>
    <message>
        <source>liver</source>
        <translation>die Leber</translation>
    </message>
    <message>
        <source>A tumour grows within the liver: choose the liver label in the Drug Delivery dock first (or grow it: Drug &gt; Liver from Points).</source>
        <translation>Ein Tumor wächst innerhalb der Leber: zuerst das Leber-Label im Dock Wirkstoffgabe wählen (oder sie wachsen lassen: Wirkstoff &gt; Leber aus Punkten).</translation>
    </message>
    <message>
        <source>%1 grown from %2 point(s): %3 ml; choose it as the %4 label in the Drug Delivery dock</source>
        <translation>%1 aus %2 Punkt(en) gewachsen: %3 ml; als %4-Label im Dock Wirkstoffgabe wählen</translation>
    </message>
    <message>
        <source>tip</source>
        <translation>Spitze</translation>
    </message>
    <message>
        <source>lesion %1</source>
        <translation>Läsion %1</translation>
    </message>
    <message>
        <source>feeder %1</source>
        <translation>Zufluss %1</translation>
    </message>
    <message>
        <source>Chemoembolization from the tip: coverage grade %1, territory %2 ml, %3 feeder(s)</source>
        <translation>Chemoembolisation von der Spitze: Abdeckungsgrad %1, Versorgungsgebiet %2 ml, %3 Zufluss/Zuflüsse</translation>
    </message>
    <message>
        <source>F&amp;low</source>
        <translation>St&amp;römung</translation>
    </message>
    <message>
        <source>Blood &amp;Flow (SPH)</source>
        <translation>Blut&amp;fluss (SPH)</translation>
    </message>
    <message>
        <source>Needle &amp;Injection (SPH, Thesis Scenario a)</source>
        <translation>Nadel&amp;injektion (SPH, Szenario a der Dissertation)</translation>
    </message>
    <message>
        <source>&amp;Wall Loads</source>
        <translation>&amp;Wandlasten</translation>
    </message>
    <message>
        <source>Time-Averaged Wall &amp;Shear Stress</source>
        <translation>Zeitgemittelte Wand&amp;schubspannung</translation>
    </message>
    <message>
        <source>&amp;Oscillatory Shear Index</source>
        <translation>&amp;Oszillatorischer Scherindex</translation>
    </message>
    <message>
        <source>Mean Wall &amp;Pressure</source>
        <translation>Mittlerer Wand&amp;druck</translation>
    </message>
    <message>
        <source>Blood Flow &amp;Parameters...</source>
        <translation>Blutfluss-&amp;Parameter...</translation>
    </message>
    <message>
        <source>Blood flow parameters</source>
        <translation>Blutfluss-Parameter</translation>
    </message>
    <message>
        <source>Inlet, outlets, figures</source>
        <translation>Einlass, Auslässe, Werte</translation>
    </message>
    <message>
        <source>Needle injection</source>
        <translation>Nadelinjektion</translation>
    </message>
    <message>
        <source>SPH solver</source>
        <translation>SPH-Löser</translation>
    </message>
    <message>
        <source>Blood flow</source>
        <translation>Blutfluss</translation>
    </message>
    <message>
        <source>The vessel ends come from the centerlines: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>Die Gefäßenden kommen aus den Mittellinien: zuerst Skelett &amp;&amp; Mittellinien ausführen.</translation>
    </message>
    <message>
        <source>Blood flow: peak velocity ratio %1 at %2 mm along the centerline (mean ratio %3), pressure drop %4 mmHg</source>
        <translation>Blutfluss: größtes Geschwindigkeitsverhältnis %1 bei %2 mm entlang der Mittellinie (mittleres Verhältnis %3), Druckabfall %4 mmHg</translation>
    </message>
    <message>
        <source>Blood flow: no stenosis figures (%1)</source>
        <translation>Blutfluss: keine Stenosewerte (%1)</translation>
    </message>
    <message>
        <source>Needle injection: %1 ml in the vessel, %2 ml collected in the box at %3 s</source>
        <translation>Nadelinjektion: %1 ml im Gefäß, %2 ml im Behälter gesammelt bei %3 s</translation>
    </message>
    <message>
        <source>TAWSS (Pa)</source>
        <translation>TAWSS (Pa)</translation>
    </message>
    <message>
        <source>OSI (0-0.5)</source>
        <translation>OSI (0-0,5)</translation>
    </message>
    <message>
        <source>mean wall pressure (Pa)</source>
        <translation>mittlerer Wanddruck (Pa)</translation>
    </message>
    <message>
        <source>Wall loads</source>
        <translation>Wandlasten</translation>
    </message>
    <message>
        <source>No wall loads yet: run Flow &gt; Blood Flow (SPH) long enough to reach its averaging window.</source>
        <translation>Noch keine Wandlasten: Strömung &gt; Blutfluss (SPH) lange genug laufen lassen, bis sein Mittelungsfenster erreicht ist.</translation>
    </message>
    <message>
        <source>, NOT CONVERGED</source>
        <translation>, NICHT KONVERGIERT</translation>
    </message>
    <message>
        <source>, STOPPED EARLY</source>
        <translation>, VORZEITIG ANGEHALTEN</translation>
    </message>
    <message>
        <source>, averaged over %1-%2 ms</source>
        <translation>, gemittelt über %1-%2 ms</translation>
    </message>
    <message>
        <source>, time-averaged</source>
        <translation>, zeitgemittelt</translation>
    </message>
    <message>
        <source>; grey: no value</source>
        <translation>; grau: kein Wert</translation>
    </message>
    <message>
        <source>The segment&apos;s anatomical name (double-click to rename) or its end nodes</source>
        <translation>Der anatomische Name des Segments (Doppelklick zum Umbenennen) oder seine Endknoten</translation>
    </message>
    <message>
        <source>Length along the centerline (mm)</source>
        <translation>Länge entlang der Mittellinie (mm)</translation>
    </message>
    <message>
        <source>Lumen radius at the segment&apos;s start (mm)</source>
        <translation>Lumenradius am Anfang des Segments (mm)</translation>
    </message>
    <message>
        <source>Lumen radius at the segment&apos;s end (mm)</source>
        <translation>Lumenradius am Ende des Segments (mm)</translation>
    </message>
    <message>
        <source>Reference lumen diameter: the median equivalent diameter of the segment&apos;s sections (mm)</source>
        <translation>Referenz-Lumendurchmesser: der Median der Äquivalenzdurchmesser der Schnitte des Segments (mm)</translation>
    </message>
    <message>
        <source>Minimal lumen diameter (equivalent) along the segment, in sections perpendicular to the centerline (mm)</source>
        <translation>Kleinster Lumendurchmesser (äquivalent) entlang des Segments, in Schnitten senkrecht zur Mittellinie (mm)</translation>
    </message>
    <message>
        <source>Diameter stenosis: 100 (1 - minimal / reference diameter) (%)</source>
        <translation>Durchmesserstenose: 100 (1 - kleinster / Referenzdurchmesser) (%)</translation>
    </message>
    <message>
        <source>Largest lumen caliper width along the segment (mm); the AAA diameter outer wall to outer wall (SVS) is the sac&apos;s row</source>
        <translation>Größte Lumen-Messweite entlang des Segments (mm); der AAA-Durchmesser von Außenwand zu Außenwand (SVS) ist die Zeile des Sacks</translation>
    </message>
    <message>
        <source>Name Segment</source>
        <translation>Segment benennen</translation>
    </message>
    <message>
        <source>Anatomical name of the segment:</source>
        <translation>Anatomischer Name des Segments:</translation>
    </message>
    <message>
        <source>Segment %1 (nodes %2-%3); double-click to rename</source>
        <translation>Segment %1 (Knoten %2-%3); Doppelklick zum Umbenennen</translation>
    </message>
    <message>
        <source>AAA maximum diameter, outer wall to outer wall (SVS): %1 mm</source>
        <translation>Größter AAA-Durchmesser, Außenwand zu Außenwand (SVS): %1 mm</translation>
    </message>
    <message>
        <source>Lumen diameter there (equivalent): %1 mm</source>
        <translation>Lumendurchmesser dort (äquivalent): %1 mm</translation>
    </message>
    <message>
        <source>Largest thrombus thickness: %1 mm</source>
        <translation>Größte Thrombusdicke: %1 mm</translation>
    </message>
    <message>
        <source>Sac volume: %1 ml</source>
        <translation>Sackvolumen: %1 ml</translation>
    </message>
    <message>
        <source>Neck diameter (outer, at the lowest renal artery): %1 mm</source>
        <translation>Halsdurchmesser (außen, an der untersten Nierenarterie): %1 mm</translation>
    </message>
    <message>
        <source>Neck length: %1 mm</source>
        <translation>Halslänge: %1 mm</translation>
    </message>
    <message>
        <source>Neck angulation: %1 degrees</source>
        <translation>Halsabwinkelung: %1 Grad</translation>
    </message>
    <message>
        <source>Right common iliac diameter (outer): %1 mm</source>
        <translation>Durchmesser A. iliaca communis rechts (außen): %1 mm</translation>
    </message>
    <message>
        <source>Left common iliac diameter (outer): %1 mm</source>
        <translation>Durchmesser A. iliaca communis links (außen): %1 mm</translation>
    </message>
    <message>
        <source>Wall thickness (assumed): %1 mm</source>
        <translation>Wanddicke (angenommen): %1 mm</translation>
    </message>
    <message>
        <source>Maximum lumen diameter %1 mm (equivalent, perpendicular)</source>
        <translation>Größter Lumendurchmesser %1 mm (äquivalent, senkrecht)</translation>
    </message>
    <message>
        <source>Segment from &amp;Points...</source>
        <translation>Aus &amp;Punkten segmentieren...</translation>
    </message>
    <message>
        <source>AAA &amp;Sac (Outer Wall, Thrombus)</source>
        <translation>AAA-&amp;Sack (Außenwand, Thrombus)</translation>
    </message>
    <message>
        <source>&amp;Along the Vessel (3D + CPR)</source>
        <translation>&amp;Entlang des Gefäßes (3D + CPR)</translation>
    </message>
    <message>
        <source>Segmentation from points</source>
        <translation>Segmentierung aus Punkten</translation>
    </message>
    <message>
        <source>AAA sac</source>
        <translation>AAA-Sack</translation>
    </message>
    <message>
        <source>The study needs a CT image and an aortic lumen label: segment the aorta first.</source>
        <translation>Die Studie braucht ein CT-Bild und ein Label des Aortenlumens: zuerst die Aorta segmentieren.</translation>
    </message>
    <message>
        <source>Segmentation Points</source>
        <translation>Segmentierungspunkte</translation>
    </message>
    <message>
        <source>Segment from points</source>
        <translation>Aus Punkten segmentieren</translation>
    </message>
    <message>
        <source>Place at least one include point inside the vessel (Place Include, then click in a slice view).</source>
        <translation>Mindestens einen Einschlusspunkt in das Gefäß setzen (Einschluss setzen, dann in eine Schnittansicht klicken).</translation>
    </message>
    <message>
        <source>Segmented %1 ml (%2 leak(s) cut)%3</source>
        <translation>%1 ml segmentiert (%2 Leck(s) geschnitten)%3</translation>
    </message>
    <message>
        <source>, replacing the label of the run before</source>
        <translation>, ersetzt das Label des vorigen Laufs</translation>
    </message>
    <message>
        <source>&amp;Research</source>
        <translation>&amp;Forschung</translation>
    </message>
    <message>
        <source>&amp;Thesis Rupture Protocol (not physiological pressures)</source>
        <translation>&amp;Rupturprotokoll der Dissertation (keine physiologischen Drücke)</translation>
    </message>
    <message>
        <source>The thrombus layer needs the AAA sac: run Vessels &gt; AAA Sac first, or set Thrombus layer to 0 in the wall mesh parameters.</source>
        <translation>Die Thrombusschicht braucht den AAA-Sack: zuerst Gefäße &gt; AAA-Sack ausführen oder die Thrombusschicht in den Wandnetz-Parametern auf 0 setzen.</translation>
    </message>
    <message>
        <source>Peak wall stress in the sac %1 kPa (99th percentile)</source>
        <translation>Größte Wandspannung im Sack %1 kPa (99. Perzentil)</translation>
    </message>
    <message>
        <source>Highest wall stress %1 kPa (no sac measured)</source>
        <translation>Höchste Wandspannung %1 kPa (kein Sack gemessen)</translation>
    </message>
    <message>
        <source>, rupture index %1</source>
        <translation>, Rupturindex %1</translation>
    </message>
    <message>
        <source>; no rupture index: give the patient&apos;s sex and family history</source>
        <translation>; kein Rupturindex: Geschlecht und Familienanamnese des Patienten angeben</translation>
    </message>
    <message>
        <source>Loading run</source>
        <translation>Lauf wird geladen</translation>
    </message>
    <message>
        <source>Click or drag to go to a frame</source>
        <translation>Klicken oder ziehen, um zu einem Bild zu gehen</translation>
    </message>
    <message>
        <source>Run Player</source>
        <translation>Laufwiedergabe</translation>
    </message>
    <message>
        <source>Run Player: %1</source>
        <translation>Laufwiedergabe: %1</translation>
    </message>
    <message>
        <source>peak (fastest 5 %)</source>
        <translation>Spitze (schnellste 5 %)</translation>
    </message>
    <message>
        <source>mean (flow rate / area)</source>
        <translation>Mittel (Flussrate / Fläche)</translation>
    </message>
    <message>
        <source>mean pressure</source>
        <translation>mittlerer Druck</translation>
    </message>
    <message>
        <source>along the centerline from the inlet (mm)</source>
        <translation>entlang der Mittellinie vom Einlass (mm)</translation>
    </message>
    <message>
        <source>velocity (m/s), time-averaged sections</source>
        <translation>Geschwindigkeit (m/s), zeitgemittelte Schnitte</translation>
    </message>
    <message>
        <source>pressure (Pa, gauge), time-averaged</source>
        <translation>Druck (Pa, relativ), zeitgemittelt</translation>
    </message>
    <message>
        <source>peak</source>
        <translation>Spitze</translation>
    </message>
    <message>
        <source>median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>segments</source>
        <translation>Segmente</translation>
    </message>
    <message>
        <source>blood particles</source>
        <translation>Blutpartikel</translation>
    </message>
    <message>
        <source>voxels</source>
        <translation>Voxel</translation>
    </message>
    <message>
        <source>cells</source>
        <translation>Zellen</translation>
    </message>
    <message>
        <source>%1 over the %2 of each frame</source>
        <translation>%1 über die %2 jedes Bildes</translation>
    </message>
    <message>
        <source>&amp;Layout</source>
        <translation>&amp;Layout</translation>
    </message>
    <message>
        <source>2 x 2</source>
        <translation>2 x 2</translation>
    </message>
    <message>
        <source>1 x 1 (the active view)</source>
        <translation>1 x 1 (die aktive Ansicht)</translation>
    </message>
    <message>
        <source>1 x 3 (axial, coronal, sagittal)</source>
        <translation>1 x 3 (axial, koronal, sagittal)</translation>
    </message>
    <message>
        <source>3D + MPR</source>
        <translation>3D + MPR</translation>
    </message>
    <message>
        <source>3D + CPR (along the vessel)</source>
        <translation>3D + CPR (entlang des Gefäßes)</translation>
    </message>
    <message>
        <source>&amp;Capture</source>
        <translation>&amp;Aufnahme</translation>
    </message>
    <message>
        <source>Screenshot of the Active &amp;View</source>
        <translation>Bildschirmfoto der aktiven &amp;Ansicht</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <comment>screenshot of the view</comment>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>Screenshot of the &amp;Window</source>
        <translation>Bildschirmfoto des &amp;Fensters</translation>
    </message>
    <message>
        <source>Movie of the 3D &amp;Rotation</source>
        <translation>Film der 3D-&amp;Drehung</translation>
    </message>
    <message>
        <source>Movie of the Played &amp;Run</source>
        <translation>Film des abgespielten &amp;Laufs</translation>
    </message>
    <message>
        <source>Capture &amp;Folder...</source>
        <translation>Aufnahme&amp;ordner...</translation>
    </message>
    <message>
        <source>Capture folder</source>
        <translation>Aufnahmeordner</translation>
    </message>
    <message>
        <source>Screenshot saved: %1</source>
        <translation>Bildschirmfoto gespeichert: %1</translation>
    </message>
    <message>
        <source>Screenshot</source>
        <translation>Bildschirmfoto</translation>
    </message>
    <message>
        <source>Movie</source>
        <translation>Film</translation>
    </message>
    <message>
        <source>Open a run first (double-click it in the study tree): the movie plays its frames.</source>
        <translation>Zuerst einen Lauf öffnen (Doppelklick im Studienbaum): der Film spielt seine Bilder.</translation>
    </message>
    <message>
        <source>Writing the movie frames...</source>
        <translation>Die Filmbilder werden geschrieben...</translation>
    </message>
    <message>
        <source>Movie cancelled: its frames were removed</source>
        <translation>Film abgebrochen: seine Bilder wurden entfernt</translation>
    </message>
    <message>
        <source>Movie saved: %1 frames in %2%3</source>
        <translation>Film gespeichert: %1 Bilder in %2%3</translation>
    </message>
    <message>
        <source>Ruler</source>
        <translation>Lineal</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>ROI</source>
        <translation>ROI</translation>
    </message>
    <message>
        <source>&amp;Measure</source>
        <translation>&amp;Messen</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Messen</translation>
    </message>
    <message>
        <source>&amp;Ruler</source>
        <translation>&amp;Lineal</translation>
    </message>
    <message>
        <source>Distance (mm): press at one end in a slice view, drag to the other, release</source>
        <translation>Abstand (mm): in einer Schnittansicht an einem Ende drücken, zum anderen ziehen, loslassen</translation>
    </message>
    <message>
        <source>&amp;Angle</source>
        <translation>&amp;Winkel</translation>
    </message>
    <message>
        <source>Angle (degrees): click the first arm&apos;s end, the vertex, then the second arm&apos;s end</source>
        <translation>Winkel (Grad): das Ende des ersten Schenkels, den Scheitel, dann das Ende des zweiten Schenkels anklicken</translation>
    </message>
    <message>
        <source>Elliptical R&amp;OI</source>
        <translation>Elliptische R&amp;OI</translation>
    </message>
    <message>
        <source>HU mean, SD and area (mm2) inside an ellipse: press at a corner of its box, drag, release</source>
        <translation>HU-Mittelwert, SD und Fläche (mm2) in einer Ellipse: an einer Ecke ihres Rahmens drücken, ziehen, loslassen</translation>
    </message>
    <message>
        <source> (Escape drops a drawing; the tool stays until clicked again)</source>
        <translation> (Escape verwirft eine Zeichnung; das Werkzeug bleibt, bis es erneut angeklickt wird)</translation>
    </message>
    <message>
        <source>&amp;Include the Selected Measurement in the Report</source>
        <translation>Ausgewählte Messung in den Bericht &amp;aufnehmen</translation>
    </message>
    <message>
        <source>Measure %1</source>
        <translation>Messung %1</translation>
    </message>
    <message>
        <source>Include &quot;%1&quot; in the report</source>
        <translation>„%1“ in den Bericht aufnehmen</translation>
    </message>
    <message>
        <source>Leave &quot;%1&quot; out of the report</source>
        <translation>„%1“ aus dem Bericht nehmen</translation>
    </message>
    <message>
        <source>Along the vessel</source>
        <translation>Entlang des Gefäßes</translation>
    </message>
    <message>
        <source>The vessel view follows a centerline: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>Die Gefäßansicht folgt einer Mittellinie: zuerst Skelett &amp;&amp; Mittellinien ausführen.</translation>
    </message>
    <message>
        <source>Virtual &amp;Endoscope</source>
        <translation>Virtuelles &amp;Endoskop</translation>
    </message>
    <message>
        <source>A camera inside the lumen flying along a centerline, with focal length and focus</source>
        <translation>Eine Kamera im Lumen, die entlang einer Mittellinie fliegt, mit Brennweite und Schärfe</translation>
    </message>
    <message>
        <source>Virtual endoscope</source>
        <translation>Virtuelles Endoskop</translation>
    </message>
    <message>
        <source>The endoscope flies along a centerline: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>Das Endoskop fliegt entlang einer Mittellinie: zuerst Skelett &amp;&amp; Mittellinien ausführen.</translation>
    </message>
    <message>
        <source>Virtual Endoscope</source>
        <translation>Virtuelles Endoskop</translation>
    </message>
    <message>
        <source>Surgical &amp;Smoke (Illustrative)</source>
        <translation>Chirurgischer &amp;Rauch (veranschaulichend)</translation>
    </message>
    <message>
        <source>&amp;Ball Drop (Thesis Demo)</source>
        <translation>&amp;Kugelfall (Demo der Dissertation)</translation>
    </message>
    <message>
        <source>&amp;Endoscopic Vessel Harvesting</source>
        <translation>&amp;Endoskopische Gefäßentnahme</translation>
    </message>
    <message>
        <source>&amp;Liver Ablation with Suction</source>
        <translation>&amp;Leberablation mit Absaugung</translation>
    </message>
    <message>
        <source>Surgical smoke</source>
        <translation>Chirurgischer Rauch</translation>
    </message>
    <message>
        <source>The EVH tunnel is drawn around a vessel&apos;s centerline: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>Der EVH-Tunnel wird um die Mittellinie eines Gefäßes gelegt: zuerst Skelett &amp;&amp; Mittellinien ausführen.</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>nicht erreicht</translation>
    </message>
    <message>
        <source>after %1 s</source>
        <translation>nach %1 s</translation>
    </message>
    <message>
        <source>Surgical smoke (illustrative): the endoscope&apos;s view 50 % obscured %1, 90 % %2; at most %3 % obscured</source>
        <translation>Chirurgischer Rauch (veranschaulichend): die Endoskopsicht zu 50 % verdeckt %1, zu 90 % %2; höchstens %3 % verdeckt</translation>
    </message>
    <message>
        <source>Smoke &amp;Parameters...</source>
        <translation>Rauch-&amp;Parameter...</translation>
    </message>
    <message>
        <source>Surgical smoke parameters</source>
        <translation>Parameter des chirurgischen Rauchs</translation>
    </message>
    <message>
        <source>Ball drop</source>
        <translation>Kugelfall</translation>
    </message>
    <message>
        <source>Vessel harvesting</source>
        <translation>Gefäßentnahme</translation>
    </message>
    <message>
        <source>Liver ablation</source>
        <translation>Leberablation</translation>
    </message>
    <message>
        <source>Query/Retrieve (&amp;PACS)...</source>
        <translation>Suchen/Abrufen (&amp;PACS)...</translation>
    </message>
    <message>
        <source>Retrieve from PACS</source>
        <translation>Aus dem PACS abrufen</translation>
    </message>
    <message>
        <source>Open or create a study first: the retrieved CT is imported into it.</source>
        <translation>Öffnen oder erstellen Sie zuerst eine Studie: Das abgerufene CT wird in sie importiert.</translation>
    </message>
    <message>
        <source>Retrieve %1 from PACS</source>
        <translation>%1 aus dem PACS abrufen</translation>
    </message>
    <message>
        <source>Send to PAC&amp;S...</source>
        <translation>An PAC&amp;S senden...</translation>
    </message>
    <message>
        <source>Send to PACS %1</source>
        <translation>An PACS %1 senden</translation>
    </message>
    <message>
        <source>Sent %1 objects to %2.</source>
        <translation>%1 Objekte an %2 gesendet.</translation>
    </message>
</context>
<context>
    <name>vsim::gui::PacsDialog</name>
    <message>
        <source>Query/Retrieve (PACS)</source>
        <translation>Suchen/Abrufen (PACS)</translation>
    </message>
    <message>
        <source>Patient ID</source>
        <translation>Patienten-ID</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Accession</source>
        <translation>Zugangsnummer</translation>
    </message>
    <message>
        <source>Modalities</source>
        <translation>Modalitäten</translation>
    </message>
    <message>
        <source>Choose or enter a PACS node, then Echo or Search.</source>
        <translation>Einen PACS-Knoten wählen oder eingeben, dann Echo oder Suchen.</translation>
    </message>
    <message>
        <source>Retrieve and Import</source>
        <translation>Abrufen und importieren</translation>
    </message>
    <message>
        <source>PACS node</source>
        <translation>PACS-Knoten</translation>
    </message>
    <message>
        <source>Saved:</source>
        <translation>Gespeichert:</translation>
    </message>
    <message>
        <source>e.g. Radiology PACS</source>
        <translation>z. B. Radiologie-PACS</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>AE title:</source>
        <translation>AE-Titel:</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <source>Our AE title, as the PACS has it registered</source>
        <translation>Unser AE-Titel, wie er im PACS eingetragen ist</translation>
    </message>
    <message>
        <source>Our AE title:</source>
        <translation>Unser AE-Titel:</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Timeout:</source>
        <translation>Zeitlimit:</translation>
    </message>
    <message>
        <source>empty: UUID-based UIDs (2.25...)</source>
        <translation>leer: UIDs aus UUIDs (2.25...)</translation>
    </message>
    <message>
        <source>The organisation&apos;s DICOM UID root for the reports and segmentations VascuSim makes</source>
        <translation>Die DICOM-UID-Wurzel der Einrichtung für die Berichte und Segmentierungen, die VascuSim erzeugt</translation>
    </message>
    <message>
        <source>UID root:</source>
        <translation>UID-Wurzel:</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Echo</source>
        <translation>Echo</translation>
    </message>
    <message>
        <source>Test the connection (C-ECHO)</source>
        <translation>Die Verbindung prüfen (C-ECHO)</translation>
    </message>
    <message>
        <source>e.g. DOE^J* (wildcards * and ?)</source>
        <translation>z. B. MUSTER^M* (Platzhalter * und ?)</translation>
    </message>
    <message>
        <source>Patient name:</source>
        <translation>Patientenname:</translation>
    </message>
    <message>
        <source>Patient ID:</source>
        <translation>Patienten-ID:</translation>
    </message>
    <message>
        <source>YYYYMMDD</source>
        <translation>JJJJMMTT</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <source>Study date:</source>
        <translation>Studiendatum:</translation>
    </message>
    <message>
        <source>Modality:</source>
        <translation>Modalität:</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Give the node a name to save it.</source>
        <translation>Geben Sie dem Knoten einen Namen, um ihn zu speichern.</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>%1 gespeichert.</translation>
    </message>
    <message>
        <source>Echo to %1...</source>
        <translation>Echo an %1...</translation>
    </message>
    <message>
        <source>%1 answers the echo.</source>
        <translation>%1 antwortet auf das Echo.</translation>
    </message>
    <message>
        <source>Echo failed: %1</source>
        <translation>Echo gescheitert: %1</translation>
    </message>
    <message>
        <source>A study date is YYYYMMDD (8 digits).</source>
        <translation>Ein Studiendatum ist JJJJMMTT (8 Ziffern).</translation>
    </message>
    <message>
        <source>Searching %1...</source>
        <translation>Suche in %1...</translation>
    </message>
    <message>
        <source>Search failed: %1</source>
        <translation>Suche gescheitert: %1</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>Studies found: %1.</source>
        <translation>Gefundene Studien: %1.</translation>
    </message>
    <message>
        <source>Patient / series</source>
        <translation>Patient / Serie</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop the echo or the query (C-CANCEL)</source>
        <translation>Echo oder Suche beenden (C-CANCEL)</translation>
    </message>
    <message>
        <source>Fetch the selected study or series (C-GET) and import its CT into the open study</source>
        <translation>Die gewählte Studie oder Serie holen (C-GET) und ihr CT in die offene Studie importieren</translation>
    </message>
    <message>
        <source>DICOM TLS</source>
        <translation>DICOM TLS</translation>
    </message>
    <message>
        <source>Encrypt the connection (DICOM TLS, BCP 195); the PACS must prove itself with a trusted certificate</source>
        <translation>Die Verbindung verschlüsseln (DICOM TLS, BCP 195); das PACS muss sich mit einem vertrauenswürdigen Zertifikat ausweisen</translation>
    </message>
    <message>
        <source>PEM files (*.pem *.crt *.cer *.key);;All files (*)</source>
        <translation>PEM-Dateien (*.pem *.crt *.cer *.key);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Trusted certificates:</source>
        <translation>Vertrauenswürdige Zertifikate:</translation>
    </message>
    <message>
        <source>The PACS&apos;s certificate or its authority&apos;s (PEM)</source>
        <translation>Das Zertifikat des PACS oder seiner Zertifizierungsstelle (PEM)</translation>
    </message>
    <message>
        <source>Our certificate:</source>
        <translation>Unser Zertifikat:</translation>
    </message>
    <message>
        <source>Ours, for a PACS that requires one (PEM; optional)</source>
        <translation>Unseres, für ein PACS, das eines verlangt (PEM; optional)</translation>
    </message>
    <message>
        <source>Our private key:</source>
        <translation>Unser privater Schlüssel:</translation>
    </message>
    <message>
        <source>The private key of our certificate (PEM, not encrypted)</source>
        <translation>Der private Schlüssel unseres Zertifikats (PEM, unverschlüsselt)</translation>
    </message>
    <message>
        <source>Find</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <source>Studies</source>
        <translation>Studien</translation>
    </message>
    <message>
        <source>Patients</source>
        <translation>Patienten</translation>
    </message>
    <message>
        <source>List studies, or patients whose studies open below them; a study opens onto its series</source>
        <translation>Studien auflisten, oder Patienten, unter denen sich ihre Studien öffnen; eine Studie öffnet sich zu ihren Serien</translation>
    </message>
    <message>
        <source>List:</source>
        <translation>Auflisten:</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>series</source>
        <translation>Serien</translation>
    </message>
    <message>
        <source>Patients found: %1.</source>
        <translation>Gefundene Patienten: %1.</translation>
    </message>
    <message>
        <source>born %1</source>
        <translation>geb. %1</translation>
    </message>
    <message>
        <source>studies</source>
        <translation>Studien</translation>
    </message>
    <message>
        <source>Wait for the running query, or Cancel it, then open this row again.</source>
        <translation>Auf die laufende Suche warten oder sie abbrechen, dann diese Zeile erneut öffnen.</translation>
    </message>
    <message>
        <source>Finding the studies of %1...</source>
        <translation>Suche die Studien von %1...</translation>
    </message>
    <message>
        <source>Finding the series of %1...</source>
        <translation>Suche die Serien von %1...</translation>
    </message>
    <message>
        <source>%1 #%2</source>
        <translation>%1 Nr. %2</translation>
    </message>
    <message>
        <source>images</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <source>Nothing found below this row.</source>
        <translation>Unter dieser Zeile nichts gefunden.</translation>
    </message>
    <message>
        <source>Found: %1.</source>
        <translation>Gefunden: %1.</translation>
    </message>
    <message>
        <source>%1 of %2, %3</source>
        <translation>%1 von %2, %3</translation>
    </message>
</context>
<context>
    <name>vsim::gui::PacsSendDialog</name>
    <message>
        <source>Send to PACS</source>
        <translation>An PACS senden</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>PACS node:</source>
        <translation>PACS-Knoten:</translation>
    </message>
    <message>
        <source>No PACS node is saved: add one in File &gt; Query/Retrieve (PACS).</source>
        <translation>Kein PACS-Knoten gespeichert: einen unter Datei &gt; Suchen/Abrufen (PACS) hinzufügen.</translation>
    </message>
    <message>
        <source>%1: none in the study</source>
        <translation>%1: keiner in der Studie</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>Newest report as a DICOM Encapsulated PDF</source>
        <translation>Neuester Bericht als DICOM Encapsulated PDF</translation>
    </message>
    <message>
        <source>Newest label as a DICOM SEG</source>
        <translation>Neuestes Label als DICOM-SEG</translation>
    </message>
    <message>
        <source>Do not send it (never into the patient&apos;s study)</source>
        <translation>Nicht senden (nie in die Studie des Patienten)</translation>
    </message>
    <message>
        <source>Send it as a new anonymized study</source>
        <translation>Als neue anonymisierte Studie senden</translation>
    </message>
    <message>
        <source>An anonymized report:</source>
        <translation>Ein anonymisierter Bericht:</translation>
    </message>
    <message>
        <source>The objects go into the patient&apos;s study, referencing the CT series, under the UID root of Query/Retrieve.</source>
        <translation>Die Objekte gehen in die Studie des Patienten, mit Verweis auf die CT-Serie, unter der UID-Wurzel aus Suchen/Abrufen.</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
</context>
<context>
    <name>vsim::gui::ParameterForm</name>
    <message>
        <source>%1 to %2%3, default %4%3</source>
        <translation>%1 bis %2%3, Standard %4%3</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Chosen for the vessel when the run starts (recorded in its provenance); untick to give this value, the default included.</source>
        <translation>Beim Start des Laufs für das Gefäß gewählt (in seiner Herkunft vermerkt); abwählen, um diesen Wert vorzugeben, auch den Standardwert.</translation>
    </message>
</context>
<context>
    <name>vsim::gui::ReportExportDialog</name>
    <message>
        <source>Export Report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>A4</source>
        <translation>A4</translation>
    </message>
    <message>
        <source>Letter</source>
        <translation>Letter</translation>
    </message>
    <message>
        <source>Anonymize (no patient name, ID, birth date or institution)</source>
        <translation>Anonymisieren (ohne Patientenname, ID, Geburtsdatum und Einrichtung)</translation>
    </message>
    <message>
        <source>Also as DICOM Encapsulated PDF (a new series of the study)</source>
        <translation>Auch als DICOM Encapsulated PDF (eine neue Serie der Studie)</translation>
    </message>
    <message>
        <source>Also the metrics as CSV and JSON</source>
        <translation>Auch die Kennzahlen als CSV und JSON</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>PDF file:</source>
        <translation>PDF-Datei:</translation>
    </message>
    <message>
        <source>Paper:</source>
        <translation>Papier:</translation>
    </message>
    <message>
        <source>The language of the report&apos;s texts and numbers; the workstation&apos;s by default</source>
        <translation>Die Sprache der Texte und Zahlen des Berichts; standardmäßig die der Arbeitsstation</translation>
    </message>
    <message>
        <source>Language:</source>
        <translation>Sprache:</translation>
    </message>
    <message>
        <source>Run the solvers&apos; validation cases into the report (seconds to a minute)</source>
        <translation>Die Validierungsfälle der Löser in den Bericht rechnen (Sekunden bis eine Minute)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::RunPlayer</name>
    <message>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <source>Range per frame</source>
        <translation>Skala je Bild</translation>
    </message>
    <message>
        <source>Previous frame</source>
        <translation>Vorheriges Bild</translation>
    </message>
    <message>
        <source>Next frame</source>
        <translation>Nächstes Bild</translation>
    </message>
    <message>
        <source>Play / pause</source>
        <translation>Abspielen / Pause</translation>
    </message>
    <message>
        <source>Playback speed (1x = %1 frames per second)</source>
        <translation>Wiedergabegeschwindigkeit (1x = %1 Bilder je Sekunde)</translation>
    </message>
    <message>
        <source>The field the frames are coloured by</source>
        <translation>Das Feld, nach dem die Bilder eingefärbt werden</translation>
    </message>
    <message>
        <source>Scale the legend to each frame instead of the whole run</source>
        <translation>Die Legende an jedes Bild statt an den ganzen Lauf anpassen</translation>
    </message>
    <message>
        <source>no frames</source>
        <translation>keine Bilder</translation>
    </message>
    <message>
        <source>frame %1 / %2, %3 %4 %5</source>
        <translation>Bild %1 / %2, %3 %4 %5</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>Druck</translation>
    </message>
</context>
<context>
    <name>vsim::gui::SegmentationPointsPanel</name>
    <message>
        <source>Aorta (with its branches)</source>
        <translation>Aorta (mit ihren Ästen)</translation>
    </message>
    <message>
        <source>Hepatic arteries</source>
        <translation>Leberarterien</translation>
    </message>
    <message>
        <source>All vessels from the points</source>
        <translation>Alle Gefäße von den Punkten</translation>
    </message>
    <message>
        <source>Aorta: every aortic segment with its branches to a length (no point needed: the abdominal aorta is found). Hepatic: a point in the aorta and one in the hepatic artery. All: every contrast vessel connected to the points, up to the path length.</source>
        <translation>Aorta: jedes Aortensegment mit seinen Ästen bis zu einer Länge (kein Punkt nötig: die Bauchaorta wird gefunden). Hepatisch: ein Punkt in der Aorta und einer in der A. hepatica. Alle: jedes kontrastierte Gefäß, das mit den Punkten verbunden ist, bis zur Weglänge.</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>target&apos;s default</source>
        <translation>Standard des Ziels</translation>
    </message>
    <message>
        <source>Path length followed from the include points (0: aorta 1000 mm, hepatic 250 mm, all 150 mm)</source>
        <translation>Von den Einschlusspunkten verfolgte Weglänge (0: Aorta 1000 mm, hepatisch 250 mm, alle 150 mm)</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>Weglänge</translation>
    </message>
    <message>
        <source>Place Include</source>
        <translation>Einschluss setzen</translation>
    </message>
    <message>
        <source>Place Exclude</source>
        <translation>Ausschluss setzen</translation>
    </message>
    <message>
        <source>Click inside the vessel in any slice view to add an include point (drag a point to move it)</source>
        <translation>In einer Schnittansicht in das Gefäß klicken, um einen Einschlusspunkt hinzuzufügen (einen Punkt ziehen, um ihn zu verschieben)</translation>
    </message>
    <message>
        <source>Click in what must stay out (heart chamber, vein, kidney, bone) to add an exclude point</source>
        <translation>In das klicken, was draußen bleiben muss (Herzkammer, Vene, Niere, Knochen), um einen Ausschlusspunkt hinzuzufügen</translation>
    </message>
    <message>
        <source>Place Stop</source>
        <translation>Stopp setzen</translation>
    </message>
    <message>
        <source>Click in a slice view where the vessel must end: a stop plane in that view&apos;s plane through the point; the fronts do not cross it away from the include points</source>
        <translation>In einer Schnittansicht dort klicken, wo das Gefäß enden muss: eine Stoppebene in der Ebene dieser Ansicht durch den Punkt; die Fronten überqueren sie nicht, von den Einschlusspunkten weg</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>z (mm)</source>
        <translation>z (mm)</translation>
    </message>
    <message>
        <source>+N include point, xN exclude point, |N stop plane (its normal in the tag&apos;s tooltip)</source>
        <translation>+N Einschlusspunkt, xN Ausschlusspunkt, |N Stoppebene (ihre Normale im Tooltip der Marke)</translation>
    </message>
    <message>
        <source>Patient frame (LPS), mm</source>
        <translation>Patientenkoordinaten (LPS), mm</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Remove the selected point</source>
        <translation>Den ausgewählten Punkt entfernen</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Segment from the points (a re-run replaces the label of the run before)</source>
        <translation>Aus den Punkten segmentieren (ein erneuter Lauf ersetzt das Label des vorigen)</translation>
    </message>
    <message>
        <source>Re-run when a point moves</source>
        <translation>Neu ausführen, wenn sich ein Punkt bewegt</translation>
    </message>
    <message>
        <source>Stop plane, normal (%1, %2, %3) towards the side the fronts do not enter</source>
        <translation>Stoppebene, Normale (%1, %2, %3) zu der Seite, die die Fronten nicht betreten</translation>
    </message>
    <message>
        <source>Segment</source>
        <comment>verb: segment the vessels</comment>
        <translation>Segmentieren</translation>
    </message>
</context>
<context>
    <name>vsim::gui::VesselViewPanel</name>
    <message>
        <source>The centerline segment shown along its length</source>
        <translation>Das entlang seiner Länge gezeigte Mittelliniensegment</translation>
    </message>
    <message>
        <source>Rotation of the curved reformation about the centerline (degrees)</source>
        <translation>Drehung der gekrümmten Reformation um die Mittellinie (Grad)</translation>
    </message>
    <message>
        <source>distance along the centerline (mm)</source>
        <translation>Abstand entlang der Mittellinie (mm)</translation>
    </message>
    <message>
        <source>lumen diameter (mm)</source>
        <translation>Lumendurchmesser (mm)</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>Drehung</translation>
    </message>
    <message>
        <source>lumen equivalent diameter (measured sections)</source>
        <translation>Äquivalenter Lumendurchmesser (gemessene Schnitte)</translation>
    </message>
    <message>
        <source>lumen diameter (2 x the centerline&apos;s radius: reads low)</source>
        <translation>Lumendurchmesser (2 x Radius der Mittellinie: misst zu niedrig)</translation>
    </message>
    <message>
        <source>Straightened CPR, %1 deg
%2 mm of centerline</source>
        <translation>Gestreckte CPR, %1 Grad
%2 mm Mittellinie</translation>
    </message>
    <message>
        <source>Perpendicular to the centerline at %1 mm
lumen %2 mm (circle: %3)</source>
        <translation>Senkrecht zur Mittellinie bei %1 mm
Lumen %2 mm (Kreis: %3)</translation>
    </message>
    <message>
        <source>equivalent diameter of the measured section</source>
        <translation>äquivalenter Durchmesser des gemessenen Schnitts</translation>
    </message>
    <message>
        <source>2 x the centerline&apos;s radius, which reads low; run the measurements</source>
        <translation>2 x Radius der Mittellinie, der zu niedrig misst; die Messungen ausführen</translation>
    </message>
    <message>
        <source>outer wall %1 mm (yellow: the largest caliper of the sac&apos;s labels here)</source>
        <translation>Außenwand %1 mm (gelb: die größte Messweite der Sack-Labels hier)</translation>
    </message>
    <message>
        <source>segment %1</source>
        <translation>Segment %1</translation>
    </message>
    <message>
        <source>%1 (%2 mm)</source>
        <translation>%1 (%2 mm)</translation>
    </message>
    <message>
        <source>%1 to %2 (%3 mm)</source>
        <translation>%1 bis %2 (%3 mm)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::WorkflowChecklist</name>
    <message>
        <source>Import a CT angiography series (DICOM folder or volume file).</source>
        <translation>Eine CT-Angiographie-Serie importieren (DICOM-Ordner oder Volumendatei).</translation>
    </message>
    <message>
        <source>Segment the contrast-filled vessel lumen (automatic seed).</source>
        <translation>Das kontrastierte Gefäßlumen segmentieren (automatischer Saatpunkt).</translation>
    </message>
    <message>
        <source>Skeleton (VDSM) and centerlines of the lumen, with diameters in mm.</source>
        <translation>Skelett (VDSM) und Mittellinien des Lumens, mit Durchmessern in mm.</translation>
    </message>
    <message>
        <source>Tetrahedral wall mesh around the lumen (wall and thrombus thickness in mm).</source>
        <translation>Tetraeder-Wandnetz um das Lumen (Wand- und Thrombusdicke in mm).</translation>
    </message>
    <message>
        <source>Wall stress (kPa) at physiological blood pressure, converged or marked so.</source>
        <translation>Wandspannung (kPa) bei physiologischem Blutdruck, konvergiert oder so markiert.</translation>
    </message>
    <message>
        <source>Blood flow (SPH): velocity ratios and wall pressure along the centerline.</source>
        <translation>Blutfluss (SPH): Geschwindigkeitsverhältnisse und Wanddruck entlang der Mittellinie.</translation>
    </message>
    <message>
        <source>Drug delivery: perfused territory, tumour coverage and feeders for the catheter tip of the Drug Delivery dock.</source>
        <translation>Wirkstoffgabe: perfundiertes Gebiet, Tumorabdeckung und Zuflüsse für die Katheterspitze im Dock Wirkstoffgabe.</translation>
    </message>
    <message>
        <source>Export the PDF report of the study&apos;s results.</source>
        <translation>Den PDF-Bericht der Ergebnisse der Studie exportieren.</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>Skeleton &amp; Centerlines</source>
        <translation>Skelett &amp; Mittellinien</translation>
    </message>
    <message>
        <source>Wall Mesh</source>
        <translation>Wandnetz</translation>
    </message>
    <message>
        <source>Wall Stress</source>
        <translation>Wandspannung</translation>
    </message>
    <message>
        <source>Blood Flow</source>
        <translation>Blutfluss</translation>
    </message>
    <message>
        <source>Drug Delivery</source>
        <translation>Wirkstoffgabe</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <source>not run</source>
        <translation>nicht ausgeführt</translation>
    </message>
    <message>
        <source>done: %1</source>
        <translation>erledigt: %1</translation>
    </message>
    <message>
        <source>stale: %1 was made from %2, which %3 has replaced since; run the step again</source>
        <translation>veraltet: %1 wurde aus %2 erstellt, das %3 inzwischen ersetzt hat; den Schritt erneut ausführen</translation>
    </message>
    <message>
        <source>done</source>
        <translation>erledigt</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>veraltet</translation>
    </message>
    <message>
        <source>%1  (%2)</source>
        <translation>%1  (%2)</translation>
    </message>
    <message>
        <source>State: %1</source>
        <translation>Zustand: %1</translation>
    </message>
    <message>
        <source>Click to run.</source>
        <translation>Klicken zum Ausführen.</translation>
    </message>
    <message>
        <source>Segment</source>
        <comment>verb: segment the vessels</comment>
        <translation>Segmentieren</translation>
    </message>
    <message>
        <source>Surgical smoke (illustrative): the liver-ablation scene with its suction and the endoscope&apos;s obscuration over time; Flow &gt; Surgical Smoke has the other scenes.</source>
        <translation>Chirurgischer Rauch (veranschaulichend): die Szene der Leberablation mit ihrer Absaugung und die Verdeckung der Endoskopsicht über die Zeit; Strömung &gt; Chirurgischer Rauch enthält die anderen Szenen.</translation>
    </message>
    <message>
        <source>Surgical Smoke</source>
        <translation>Chirurgischer Rauch</translation>
    </message>
</context>
<context>
    <name>vsim::imaging::AneurysmSac</name>
    <message>
        <source>largest outer-wall to outer-wall caliper perpendicular to the centerline of the outer contour, thrombus and wall included (SVS 2018)</source>
        <translation>größte Caliperweite von Außenwand zu Außenwand senkrecht zur Mittellinie der Außenkontur, Thrombus und Wand eingeschlossen (SVS 2018)</translation>
    </message>
    <message>
        <source>patient position (LPS) of the centre of that cross-section</source>
        <translation>Patientenposition (LPS) des Mittelpunkts dieses Querschnitts</translation>
    </message>
    <message>
        <source>equivalent diameter of the contrast lumen&apos;s perpendicular cross-section there</source>
        <translation>äquivalenter Durchmesser des senkrechten Querschnitts des kontrastierten Lumens dort</translation>
    </message>
    <message>
        <source>outer diameter perpendicular to the centerline at the origin of the lowest renal artery (the median 3 to 8 mm below it, clear of the branch; without the renal arteries in the label: the narrowest within 80 mm above the widest section)</source>
        <translation>Außendurchmesser senkrecht zur Mittellinie am Abgang der untersten Nierenarterie (der Median 3 bis 8 mm darunter, abseits des Abgangs; ohne Nierenarterien im Label: der engste innerhalb von 80 mm oberhalb des weitesten Querschnitts)</translation>
    </message>
    <message>
        <source>centerline length from the lowest renal artery&apos;s origin to the start of the sac</source>
        <translation>Mittellinienlänge vom Abgang der untersten Nierenarterie bis zum Beginn des Aneurysmasacks</translation>
    </message>
    <message>
        <source>angle between the neck axis (lowest renal artery to the sac&apos;s start) and the sac axis (the sac&apos;s start to its end)</source>
        <translation>Winkel zwischen der Halsachse (unterste Nierenarterie bis Beginn des Aneurysmasacks) und der Sackachse (Beginn bis Ende des Aneurysmasacks)</translation>
    </message>
    <message>
        <source>patient position (LPS z) of the lowest renal artery&apos;s origin</source>
        <translation>Patientenposition (LPS z) des Abgangs der untersten Nierenarterie</translation>
    </message>
    <message>
        <source>outer diameter of the left common iliac artery perpendicular to its centerline: the median 10 to 40 mm below the crotch</source>
        <translation>Außendurchmesser der linken A. iliaca communis senkrecht zu ihrer Mittellinie: der Median 10 bis 40 mm unterhalb der Gabelung</translation>
    </message>
    <message>
        <source>outer diameter of the right common iliac artery perpendicular to its centerline: the median 10 to 40 mm below the crotch</source>
        <translation>Außendurchmesser der rechten A. iliaca communis senkrecht zu ihrer Mittellinie: der Median 10 bis 40 mm unterhalb der Gabelung</translation>
    </message>
    <message>
        <source>1.5 x the neck diameter (30 mm without a neck)</source>
        <translation>1,5 x Halsdurchmesser (ohne Hals 30 mm)</translation>
    </message>
    <message>
        <source>assumed, not measured: the wall is that shell inside the outer contour</source>
        <translation>angenommen, nicht gemessen: die Wand ist diese Schale innerhalb der Außenkontur</translation>
    </message>
    <message>
        <source>volume inside the outer contour between the perpendicular planes at the sac&apos;s ends</source>
        <translation>Volumen innerhalb der Außenkontur zwischen den senkrechten Ebenen an den Enden des Aneurysmasacks</translation>
    </message>
    <message>
        <source>centerline length of the sac (outer diameter over the threshold, contiguous)</source>
        <translation>Mittellinienlänge des Aneurysmasacks (Außendurchmesser über der Schwelle, zusammenhängend)</translation>
    </message>
    <message>
        <source>largest distance from the lumen to the wall&apos;s inner surface along the rays of an axial section, within the sac</source>
        <translation>größter Abstand vom Lumen zur Innenfläche der Wand entlang der Strahlen eines axialen Querschnitts, innerhalb des Aneurysmasacks</translation>
    </message>
</context>
<context>
    <name>vsim::viz::SliceView</name>
    <message>
        <source>W %1  L %2</source>
        <translation>F %1  L %2</translation>
    </message>
    <message>
        <source>MIP slab %1 mm</source>
        <translation>MIP-Schicht %1 mm</translation>
    </message>
    <message>
        <source>Im %1/%2  %3 = %4 mm</source>
        <translation>Bild %1/%2  %3 = %4 mm</translation>
    </message>
    <message>
        <source>(%1, %2, %3) mm</source>
        <translation>(%1, %2, %3) mm</translation>
    </message>
    <message>
        <source>%1 HU</source>
        <translation>%1 HU</translation>
    </message>
</context>
</TS>
