<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>QObject</name>
    <message>
        <location filename="../app/gui/main.cpp" line="46"/>
        <source>Writing the demo study (aaa phantom)...</source>
        <translation>Demo-Studie wird geschrieben (AAA-Phantom)...</translation>
    </message>
    <message>
        <location filename="../app/gui/ArtifactCommands.cpp" line="11"/>
        <source>Rename &quot;%1&quot;</source>
        <translation>&quot;%1&quot; umbenennen</translation>
    </message>
    <message>
        <location filename="../app/gui/ArtifactCommands.cpp" line="29"/>
        <source>Delete &quot;%1&quot;</source>
        <translation>&quot;%1&quot; löschen</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="56"/>
        <source>cannot be placed</source>
        <translation>nicht platzierbar</translation>
    </message>
    <message>
        <location filename="../app/gui/LabelEditSession.cpp" line="13"/>
        <source>Paint label</source>
        <translation>Label malen</translation>
    </message>
    <message>
        <location filename="../app/gui/LabelEditSession.cpp" line="13"/>
        <source>Erase label</source>
        <translation>Label radieren</translation>
    </message>
</context>
<context>
    <name>vsim::gui::DicomImportDialog</name>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="64"/>
        <source>Import DICOM</source>
        <translation>DICOM importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="69"/>
        <source>Folder, DICOMDIR or file</source>
        <translation>Ordner, DICOMDIR oder Datei</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="70"/>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="71"/>
        <source>Scan</source>
        <translation>Einlesen</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="79"/>
        <source>Patient / study / series</source>
        <translation>Patient / Studie / Serie</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="79"/>
        <source>Modality</source>
        <translation>Modalität</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="79"/>
        <source>Slices</source>
        <translation>Schichten</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="79"/>
        <source>Voxel spacing (mm)</source>
        <translation>Voxelabstand (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="80"/>
        <source>Warnings</source>
        <translation>Warnungen</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="88"/>
        <source>Stop</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="96"/>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="106"/>
        <source>DICOM folder</source>
        <translation>DICOM-Ordner</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="157"/>
        <source>Reading DICOM headers...</source>
        <translation>DICOM-Header werden gelesen...</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="202"/>
        <source>(no name)</source>
        <translation>(kein Name)</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="203"/>
        <source>no ID</source>
        <translation>keine ID</translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="209"/>
        <location filename="../app/gui/DicomImportDialog.cpp" line="219"/>
        <source>(no description)</source>
        <translation>(keine Beschreibung)</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/DicomImportDialog.cpp" line="229"/>
        <source>%n file(s), %1 series</source>
        <translation>
            <numerusform>%n Datei, %1 Serien</numerusform>
            <numerusform>%n Dateien, %1 Serien</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/DicomImportDialog.cpp" line="240"/>
        <source> (making previews)</source>
        <translation> (Vorschauen werden erstellt)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::DrugDeliveryPanel</name>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="48"/>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="108"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="54"/>
        <source>x, y, z mm; empty: the root</source>
        <translation>x, y, z mm; leer: die Wurzel</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="56"/>
        <source>x, y, z, radius mm; empty: none</source>
        <translation>x, y, z, Radius mm; leer: keiner</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="58"/>
        <source>x, y, z; ... mm; empty: the first branches</source>
        <translation>x, y, z; ... mm; leer: die ersten Äste</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="61"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="62"/>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="63"/>
        <source>Pick</source>
        <translation>Wählen</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="64"/>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="65"/>
        <source>Run</source>
        <translation>Berechnen</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="74"/>
        <source>Catheter tip</source>
        <translation>Katheterspitze</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="75"/>
        <source>Tumour</source>
        <translation>Tumor</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="76"/>
        <source>Tumour radius (picked)</source>
        <translation>Tumorradius (gewählt)</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="77"/>
        <source>Control points</source>
        <translation>Kontrollpunkte</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="88"/>
        <source>Outlet</source>
        <translation>Auslass</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="88"/>
        <source>Drug share (%)</source>
        <translation>Wirkstoffanteil (%)</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="88"/>
        <source>Arrival (s)</source>
        <translation>Ankunft (s)</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="108"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="160"/>
        <source>Tip pressure %1 mmHg; last outlet reached after %2 s.</source>
        <translation>Druck an der Spitze %1 mmHg; letzter Auslass nach %2 s erreicht.</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="163"/>
        <source>&lt;br&gt;Control point %1: drug %2 ml/min two-phase, %3 ml/min liquid (%4 % lower)</source>
        <translation>&lt;br&gt;Kontrollpunkt %1: Wirkstoff %2 ml/min zweiphasig, %3 ml/min flüssig (%4 % weniger)</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="167"/>
        <source>&lt;br&gt;Tumour share %1 % (%2 outlets).</source>
        <translation>&lt;br&gt;Tumoranteil %1 % (%2 Auslässe).</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="169"/>
        <source>&lt;br&gt;Best tip: node %1 delivers %2 % to the tumour.</source>
        <translation>&lt;br&gt;Beste Spitze: Knoten %1 bringt %2 % in den Tumor.</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="183"/>
        <source>never</source>
        <translation>nie</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="206"/>
        <source>Drug flow (ml/min)</source>
        <translation>Wirkstofffluss (ml/min)</translation>
    </message>
    <message>
        <location filename="../app/gui/DrugDeliveryPanel.cpp" line="232"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
</context>
<context>
    <name>vsim::gui::InteractiveWall</name>
    <message>
        <location filename="../app/gui/InteractiveWall.cpp" line="75"/>
        <source>von Mises (kPa)</source>
        <translation>von Mises (kPa)</translation>
    </message>
</context>
<context>
    <name>vsim::gui::MainWindow</name>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="27"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="28"/>
        <source>&amp;New Study...</source>
        <translation>&amp;Neue Studie...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="29"/>
        <location filename="../app/gui/MainWindowMenus.cpp" line="57"/>
        <source>Study folder (*.vsim)</source>
        <translation>Studienordner (*.vsim)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="33"/>
        <source>&amp;Open Study...</source>
        <translation>Studie ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="38"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="41"/>
        <source>Import &amp;DICOM...</source>
        <translation>&amp;DICOM importieren...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="41"/>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="43"/>
        <source>&amp;Import Volume...</source>
        <translation>Volumen &amp;importieren...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="43"/>
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="48"/>
        <source>Import &amp;Label...</source>
        <translation>&amp;Label importieren...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="49"/>
        <source>Import label (a mask on the CT&apos;s grid)</source>
        <translation>Label importieren (eine Maske auf dem Raster des CT)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="55"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="56"/>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="62"/>
        <source>Export &amp;Report...</source>
        <translation>&amp;Bericht exportieren...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="62"/>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="65"/>
        <source>&amp;Close Window</source>
        <translation>Fenster &amp;schließen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="66"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="68"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="69"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="71"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="76"/>
        <source>Re&amp;name Artifact...</source>
        <translation>Artefakt &amp;umbenennen...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="81"/>
        <source>Rename artifact</source>
        <translation>Artefakt umbenennen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="81"/>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="87"/>
        <source>&amp;Delete Artifact</source>
        <translation>Artefakt &amp;löschen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="97"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="98"/>
        <source>Window/Level: &amp;CTA</source>
        <translation>Fenster: &amp;CTA</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="99"/>
        <source>Window/Level: &amp;Soft Tissue</source>
        <translation>Fenster: &amp;Weichteil</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="100"/>
        <source>Window/Level: &amp;Bone</source>
        <translation>Fenster: &amp;Knochen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="102"/>
        <source>3D: &amp;Anterior View</source>
        <translation>3D: &amp;Ansicht von vorn</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="107"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="108"/>
        <source>&amp;About VascuSim</source>
        <translation>Ü&amp;ber VascuSim</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="126"/>
        <source>About VascuSim</source>
        <translation>Über VascuSim</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowMenus.cpp" line="127"/>
        <source>&lt;h3&gt;VascuSim&lt;/h3&gt;&lt;p&gt;Patient-specific physics for vascular procedure planning.&lt;/p&gt;&lt;p&gt;Results support planning and need clinical judgement.&lt;/p&gt;&lt;table&gt;%1&lt;/table&gt;</source>
        <translation>&lt;h3&gt;VascuSim&lt;/h3&gt;&lt;p&gt;Patientenspezifische Physik für die Planung vaskulärer Eingriffe.&lt;/p&gt;&lt;p&gt;Die Ergebnisse unterstützen die Planung und erfordern ärztliches Urteil.&lt;/p&gt;&lt;table&gt;%1&lt;/table&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="61"/>
        <source>%1: cancelled, nothing changed</source>
        <translation>%1: abgebrochen, nichts geändert</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="64"/>
        <source>%1: done</source>
        <translation>%1: fertig</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="84"/>
        <source>Artifact</source>
        <translation>Artefakt</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="84"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="84"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="101"/>
        <source>Study</source>
        <translation>Studie</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="109"/>
        <location filename="../app/gui/MainWindow.cpp" line="115"/>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="109"/>
        <location filename="../app/gui/MainWindow.cpp" line="117"/>
        <source>Segment</source>
        <translation>Segmentieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="109"/>
        <location filename="../app/gui/MainWindow.cpp" line="119"/>
        <source>Skeleton &amp;&amp; Centerlines</source>
        <translation>Skelett &amp;&amp; Mittellinien</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="109"/>
        <location filename="../app/gui/MainWindow.cpp" line="121"/>
        <source>Mesh</source>
        <translation>Netz</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="109"/>
        <location filename="../app/gui/MainWindow.cpp" line="123"/>
        <source>Simulate</source>
        <translation>Simulieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="110"/>
        <location filename="../app/gui/MainWindow.cpp" line="125"/>
        <location filename="../app/gui/MainWindowReport.cpp" line="76"/>
        <location filename="../app/gui/MainWindowReport.cpp" line="80"/>
        <location filename="../app/gui/MainWindowReport.cpp" line="118"/>
        <location filename="../app/gui/MainWindowReport.cpp" line="140"/>
        <source>Report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="128"/>
        <source>Workflow</source>
        <translation>Arbeitsablauf</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="140"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="168"/>
        <source>No study</source>
        <translation>Keine Studie</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="170"/>
        <source>%1[*] - VascuSim</source>
        <translation>%1[*] - VascuSim</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="170"/>
        <source>%1 (read-only) - VascuSim</source>
        <translation>%1 (schreibgeschützt) - VascuSim</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="190"/>
        <source>damaged</source>
        <translation>beschädigt</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/MainWindow.cpp" line="195"/>
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="201"/>
        <source>%1, made by &quot;%2&quot; on %3</source>
        <translation>%1, erzeugt von &quot;%2&quot; am %3</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="213"/>
        <source>%1 failed</source>
        <translation>%1 fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="234"/>
        <source>Opened read-only: the study is being written by %1</source>
        <translation>Schreibgeschützt geöffnet: die Studie wird von %1 geschrieben</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="238"/>
        <source>Study in use</source>
        <translation>Studie in Gebrauch</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="239"/>
        <source>The study is being written by %1.
Open it read-only, or break the lock if you are sure that program no longer runs.</source>
        <translation>Die Studie wird von %1 geschrieben.
Schreibgeschützt öffnen, oder die Sperre aufheben, wenn Sie sicher sind, dass dieses Programm nicht mehr läuft.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="242"/>
        <source>Open Read-Only</source>
        <translation>Schreibgeschützt öffnen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="243"/>
        <source>Break the Lock...</source>
        <translation>Sperre aufheben...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="248"/>
        <source>Break the lock</source>
        <translation>Sperre aufheben</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="249"/>
        <source>If %1 still runs, both programs will write the study and results can be lost. Break the lock?</source>
        <translation>Wenn %1 noch läuft, schreiben beide Programme die Studie, und Ergebnisse können verloren gehen. Sperre aufheben?</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="276"/>
        <location filename="../app/gui/MainWindowMenus.cpp" line="34"/>
        <source>Open study</source>
        <translation>Studie öffnen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="296"/>
        <source>Study opened with problems</source>
        <translation>Studie mit Problemen geöffnet</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="315"/>
        <location filename="../app/gui/MainWindowMenus.cpp" line="29"/>
        <source>New study</source>
        <translation>Neue Studie</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowImport.cpp" line="24"/>
        <location filename="../app/gui/MainWindowImport.cpp" line="27"/>
        <location filename="../app/gui/MainWindowMenus.cpp" line="44"/>
        <source>Import volume</source>
        <translation>Volumen importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowImport.cpp" line="32"/>
        <location filename="../app/gui/MainWindowImport.cpp" line="65"/>
        <location filename="../app/gui/MainWindowImport.cpp" line="121"/>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowImport.cpp" line="44"/>
        <location filename="../app/gui/MainWindowImport.cpp" line="51"/>
        <source>Import label</source>
        <translation>Label importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowImport.cpp" line="44"/>
        <source>The study has no CT image for the label&apos;s grid: import the CT first.</source>
        <translation>Die Studie hat kein CT-Bild für das Raster des Labels: zuerst das CT importieren.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowImport.cpp" line="89"/>
        <source>Not Hounsfield units</source>
        <translation>Keine Hounsfield-Einheiten</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowImport.cpp" line="90"/>
        <source>%1

Rescale to HU (HU = slope x stored value + intercept):</source>
        <translation>%1

Umrechnung in HU (HU = Steigung x gespeicherter Wert + Achsenabschnitt):</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowImport.cpp" line="107"/>
        <location filename="../app/gui/MainWindowImport.cpp" line="115"/>
        <source>Import DICOM</source>
        <translation>DICOM importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="326"/>
        <location filename="../app/gui/MainWindow.cpp" line="397"/>
        <source>Save study</source>
        <translation>Studie speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="339"/>
        <location filename="../app/gui/MainWindowMenus.cpp" line="57"/>
        <source>Save study as</source>
        <translation>Studie speichern unter</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="358"/>
        <source>Show image</source>
        <translation>Bild anzeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="383"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="384"/>
        <source>Save the changes to this study before closing?</source>
        <translation>Änderungen an dieser Studie vor dem Schließen speichern?</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="56"/>
        <source>Length (mm)</source>
        <translation>Länge (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="56"/>
        <source>Start r (mm)</source>
        <translation>Anfangs-r (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="56"/>
        <source>End r (mm)</source>
        <translation>End-r (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="56"/>
        <source>Segment</source>
        <comment>a vessel segment (noun)</comment>
        <translation>Segment</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="57"/>
        <source>Reference Ø (mm)</source>
        <translation>Referenz-Ø (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="57"/>
        <source>Minimal Ø (mm)</source>
        <translation>Minimaler Ø (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="58"/>
        <source>Stenosis (%)</source>
        <translation>Stenose (%)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="58"/>
        <source>Max Ø (mm)</source>
        <translation>Max. Ø (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="70"/>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="98"/>
        <source>Maximum diameter %1 mm</source>
        <translation>Maximaler Durchmesser %1 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="112"/>
        <source>V&amp;essels</source>
        <translation>&amp;Gefäße</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="113"/>
        <source>&amp;Segment Vessels</source>
        <translation>Gefäße &amp;segmentieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="115"/>
        <source>Segment from the &amp;Cursor</source>
        <translation>Ab dem &amp;Cursor segmentieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="118"/>
        <source>S&amp;keleton and Centerlines</source>
        <translation>S&amp;kelett und Mittellinien</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="121"/>
        <source>&amp;Edit Label (Brush)</source>
        <translation>Label &amp;bearbeiten (Pinsel)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="122"/>
        <source>&amp;Parameters...</source>
        <translation>&amp;Parameter...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="127"/>
        <source>Vessel parameters</source>
        <translation>Gefäßparameter</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="128"/>
        <source>Segmentation</source>
        <translation>Segmentierung</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="145"/>
        <location filename="../app/gui/MainWindowVessels.cpp" line="157"/>
        <location filename="../app/gui/MainWindowVessels.cpp" line="179"/>
        <source>Segment vessels</source>
        <translation>Gefäße segmentieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="145"/>
        <source>The study has no CT image: import one first.</source>
        <translation>Die Studie enthält kein CT-Bild: zuerst eines importieren.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="190"/>
        <location filename="../app/gui/MainWindowVessels.cpp" line="203"/>
        <location filename="../app/gui/MainWindowVessels.cpp" line="232"/>
        <source>Skeleton and centerlines</source>
        <translation>Skelett und Mittellinien</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="28"/>
        <source>Label Editing</source>
        <translation>Label-Bearbeitung</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="31"/>
        <source>Paint</source>
        <translation>Malen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="32"/>
        <source>Erase</source>
        <translation>Radieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="38"/>
        <source>Paint vessel voxels with the left button in any MPR view (one undo step per stroke)</source>
        <translation>Gefäßvoxel mit der linken Maustaste in einer MPR-Ansicht malen (ein Rückgängig-Schritt pro Strich)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="39"/>
        <source>Erase vessel voxels with the left button in any MPR view</source>
        <translation>Gefäßvoxel mit der linken Maustaste in einer MPR-Ansicht radieren</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="40"/>
        <source> Radius </source>
        <translation> Radius </translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="47"/>
        <source>Apply Edits</source>
        <translation>Änderungen übernehmen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="48"/>
        <source>Discard Edits</source>
        <translation>Änderungen verwerfen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="49"/>
        <source>Add the edited label to the study as a new artifact (the original stays)</source>
        <translation>Das bearbeitete Label als neues Artefakt zur Studie hinzufügen (das Original bleibt)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="72"/>
        <source>Label edits: %1 voxels painted, %2 erased</source>
        <translation>Label-Änderungen: %1 Voxel gemalt, %2 radiert</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="94"/>
        <location filename="../app/gui/MainWindowVessels.cpp" line="190"/>
        <source>The study has no vessel label: segment the vessels first.</source>
        <translation>Die Studie enthält keine Gefäßmaske: zuerst die Gefäße segmentieren.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="94"/>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="104"/>
        <source>Edit label</source>
        <translation>Label bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowLabelEditing.cpp" line="152"/>
        <source>Apply label edits</source>
        <translation>Label-Änderungen übernehmen</translation>
    </message>
    <message>
        <source>Vessel surface</source>
        <translation type="vanished">Gefäßoberfläche</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="129"/>
        <location filename="../app/gui/MainWindowVessels.cpp" line="233"/>
        <source>Skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowVessels.cpp" line="130"/>
        <location filename="../app/gui/MainWindowVessels.cpp" line="234"/>
        <source>Centerlines</source>
        <translation>Mittellinien</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="33"/>
        <source>&amp;Wall</source>
        <translation>&amp;Wand</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="34"/>
        <source>Build &amp;Wall Mesh</source>
        <translation>&amp;Wandnetz erzeugen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="35"/>
        <source>Wall Stress at &amp;Blood Pressure</source>
        <translation>Wandspannung bei &amp;Blutdruck</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="37"/>
        <source>&amp;Thesis Rupture Protocol</source>
        <translation>&amp;Ruptur-Protokoll der Dissertation</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="38"/>
        <source>&amp;Interactive Protocol</source>
        <translation>&amp;Interaktives Protokoll</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="40"/>
        <source>Wall &amp;Parameters...</source>
        <translation>Wand-&amp;Parameter...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="41"/>
        <source>Wall parameters</source>
        <translation>Wandparameter</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="42"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="54"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="61"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="68"/>
        <source>Wall mesh</source>
        <translation>Wandnetz</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="42"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="84"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="102"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="134"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="151"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="191"/>
        <source>Wall mechanics</source>
        <translation>Wandmechanik</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="54"/>
        <source>The wall needs a vessel label and centerlines: run Segment and Skeleton &amp;&amp; Centerlines first.</source>
        <translation>Die Wand braucht ein Gefäßlabel und Mittellinien: zuerst Segmentieren und Skelett &amp;&amp; Mittellinien ausführen.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="69"/>
        <source>Wall: %1 elements, smallest dihedral angle %2 deg</source>
        <translation>Wand: %1 Elemente, kleinster Diederwinkel %2 Grad</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="84"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="134"/>
        <source>Build the wall mesh first (Wall &gt; Build Wall Mesh).</source>
        <translation>Zuerst das Wandnetz erzeugen (Wand &gt; Wandnetz erzeugen).</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="91"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="100"/>
        <source>Wall stress</source>
        <translation>Wandspannung</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="91"/>
        <source>Thesis rupture protocol</source>
        <translation>Ruptur-Protokoll der Dissertation</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="103"/>
        <source>Read these results with care: %1</source>
        <translation>Diese Ergebnisse mit Vorsicht lesen: %1</translation>
    </message>
    <message>
        <source>The run stopped early: %1</source>
        <translation type="vanished">Die Rechnung endete vorzeitig: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="105"/>
        <source>Peak wall stress %1 kPa, peak rupture index %2</source>
        <translation>Höchste Wandspannung %1 kPa, höchster Rupturindex %2</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="121"/>
        <source>von Mises (kPa), NOT CONVERGED</source>
        <translation>von Mises (kPa), NICHT KONVERGIERT</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="122"/>
        <source>von Mises (kPa), STOPPED EARLY</source>
        <translation>von Mises (kPa), VORZEITIG BEENDET</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="123"/>
        <source>von Mises (kPa)</source>
        <translation>von Mises (kPa)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="161"/>
        <location filename="../app/gui/MainWindowWall.cpp" line="178"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="167"/>
        <source>0 mmHg</source>
        <translation>0 mmHg</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="168"/>
        <source>Tear at %1 MPa</source>
        <translation>Reißen bei %1 MPa</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="171"/>
        <source>Pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="175"/>
        <source>Drag the wall with the left button in the 3D view.</source>
        <translation>Die Wand in der 3D-Ansicht mit der linken Maustaste ziehen.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="178"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="182"/>
        <source>%1 mmHg</source>
        <translation>%1 mmHg</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="187"/>
        <source>%1 frames/s, peak von Mises %2 kPa</source>
        <translation>%1 Bilder/s, höchste von-Mises-Spannung %2 kPa</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="191"/>
        <source>The simulation paused: %1</source>
        <translation>Die Simulation hält an: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowWall.cpp" line="193"/>
        <source>Interactive Wall</source>
        <translation>Interaktive Wand</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="25"/>
        <source>&amp;Drug</source>
        <translation>&amp;Wirkstoff</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="26"/>
        <source>Drug &amp;Delivery</source>
        <translation>Wirkstoff&amp;gabe</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="29"/>
        <source>Drug &amp;Parameters...</source>
        <translation>Wirkstoff&amp;parameter...</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="30"/>
        <source>Drug delivery parameters</source>
        <translation>Parameter der Wirkstoffgabe</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="30"/>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="41"/>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="50"/>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="59"/>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="70"/>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="82"/>
        <source>Drug delivery</source>
        <translation>Wirkstoffgabe</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="41"/>
        <source>The network needs centerlines: run Skeleton &amp;&amp; Centerlines first.</source>
        <translation>Das Netzwerk braucht Mittellinien: zuerst Skelett &amp;&amp; Mittellinien ausführen.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="50"/>
        <source>The tip needs three numbers (mm) and the tumour four (centre and radius).</source>
        <translation>Die Spitze braucht drei Zahlen (mm), der Tumor vier (Mitte und Radius).</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="59"/>
        <source>The tumour&apos;s radius must be positive.</source>
        <translation>Der Radius des Tumors muss positiv sein.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="70"/>
        <source>Control points are x, y, z in mm, separated by &apos;;&apos;.</source>
        <translation>Kontrollpunkte sind x, y, z in mm, getrennt durch &apos;;&apos;.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="95"/>
        <source>Drug flow</source>
        <translation>Wirkstofffluss</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="107"/>
        <source>Drug Delivery</source>
        <translation>Wirkstoffgabe</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowNetwork.cpp" line="115"/>
        <source>Drug delivery: %1 outlets, last reached after %2 s</source>
        <translation>Wirkstoffgabe: %1 Auslässe, der letzte nach %2 s erreicht</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowReport.cpp" line="76"/>
        <source>No PDF viewer opened %1.</source>
        <translation>Kein PDF-Betrachter hat %1 geöffnet.</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowReport.cpp" line="100"/>
        <source>Replace files</source>
        <translation>Dateien ersetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowReport.cpp" line="101"/>
        <source>These files exist already:
%1
Replace them?</source>
        <translation>Diese Dateien gibt es schon:
%1
Ersetzen?</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowReport.cpp" line="141"/>
        <source>Report written to %1</source>
        <translation>Bericht geschrieben nach %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindowScene.cpp" line="117"/>
        <source>Preparing the views</source>
        <translation>Ansichten werden vorbereitet</translation>
    </message>
</context>
<context>
    <name>vsim::gui::ReportExportDialog</name>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="17"/>
        <source>Export Report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="19"/>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="21"/>
        <source>Report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="21"/>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="29"/>
        <source>A4</source>
        <translation>A4</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="30"/>
        <source>Letter</source>
        <translation>Letter</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="31"/>
        <source>Anonymize (no patient name, ID, birth date or institution)</source>
        <translation>Anonymisieren (ohne Patientenname, ID, Geburtsdatum und Einrichtung)</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="32"/>
        <source>Also as DICOM Encapsulated PDF (a new series of the study)</source>
        <translation>Auch als DICOM Encapsulated PDF (eine neue Serie der Studie)</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="33"/>
        <source>Also the metrics as CSV and JSON</source>
        <translation>Auch die Kennzahlen als CSV und JSON</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="35"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="39"/>
        <source>PDF file:</source>
        <translation>PDF-Datei:</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportExportDialog.cpp" line="40"/>
        <source>Paper:</source>
        <translation>Papier:</translation>
    </message>
</context>
</TS>
