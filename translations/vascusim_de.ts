<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>vsim::gui::MainWindow</name>
    <message><source>&amp;File</source><translation>&amp;Datei</translation></message>
    <message><source>&amp;Edit</source><translation>&amp;Bearbeiten</translation></message>
    <message><source>&amp;View</source><translation>&amp;Ansicht</translation></message>
    <message><source>&amp;Help</source><translation>&amp;Hilfe</translation></message>
    <message><source>Study</source><translation>Studie</translation></message>
    <message><source>Workflow</source><translation>Arbeitsablauf</translation></message>
    <message><source>Cancel</source><translation>Abbrechen</translation></message>
</context>
</TS>
