<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>App::Property</name>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="18"/>
        <source>The joints it moves</source>
        <translation>Die Gelenke, die sie bewegt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="20"/>
        <source>Per joint: for a double pivot, the point its part turns about to get here</source>
        <translation>Je Gelenk: bei einem Doppelgelenk der Punkt, um den sich sein Teil dreht, um hierher zu gelangen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="21"/>
        <source>The part the joint moves</source>
        <translation>Das Teil, das das Gelenk bewegt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="22"/>
        <source>The part it hangs on, which carries it along when it moves; empty: the ground</source>
        <translation>Das Teil, an dem es hängt und das es mitnimmt, wenn es sich bewegt; leer: der Boden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="26"/>
        <source>The edge of one of the part&apos;s boxes it turns about</source>
        <translation>Die Kante eines Quaders des Teils, um die es dreht</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="29"/>
        <source>The direction it slides along</source>
        <translation>Die Richtung, in die es gleitet</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="32"/>
        <source>The face of the part&apos;s box with the pivot</source>
        <translation>Die Fläche des Quaders des Teils mit dem Drehpunkt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="34"/>
        <source>The pivot on the part (placed by the solve)</source>
        <translation>Der Drehpunkt am Teil (vom Lösen gesetzt)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="36"/>
        <source>The face of the base&apos;s box, in the same plane, with the other pivot</source>
        <translation>Die Fläche des Quaders der Basis, in derselben Ebene, mit dem anderen Drehpunkt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="39"/>
        <source>The pivot on the base (placed by the solve)</source>
        <translation>Der Drehpunkt an der Basis (vom Lösen gesetzt)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="31"/>
        <source>Smallest size of a box along any axis</source>
        <translation>Kleinste Größe eines Quaders entlang jeder Achse</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="33"/>
        <source>Least wall around a cavity on its sides that are not openings</source>
        <translation>Kleinste Wand um einen Hohlraum an seinen Seiten, die keine Öffnungen sind</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="37"/>
        <source>Box coordinates you changed since the last solve keep their new value while the rest adapts</source>
        <translation>Quaderkoordinaten, die Sie seit dem letzten Lösen geändert haben, behalten ihren neuen Wert, während sich der Rest anpasst</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="40"/>
        <source>The configuration the Configurations panel last showed; new relationships hold in it</source>
        <translation>Die Konfiguration, die das Konfigurationen-Fenster zuletzt zeigte; neue Beziehungen gelten in ihr</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="43"/>
        <source>Solved, or the relationships in conflict</source>
        <translation>Gelöst, oder die Beziehungen im Widerspruch</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="45"/>
        <source>Largest constraint violation after the solve, mm</source>
        <translation>Größte Verletzung einer Vorgabe nach dem Lösen, mm</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="48"/>
        <source>Parts a conflict blames besides its relationships&apos; (overlapping parts, thin walls)</source>
        <translation>Teile, die ein Widerspruch außer denen seiner Beziehungen nennt (überlappende Teile, dünne Wände)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="51"/>
        <source>What the last solve changed: box, size old → new, how far it moved</source>
        <translation>Was das letzte Lösen geändert hat: Quader, Größe alt → neu, wie weit er verschoben wurde</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="54"/>
        <source>Box coordinates after the last solve (JSON)</source>
        <translation>Quaderkoordinaten nach dem letzten Lösen (JSON)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="56"/>
        <source>Box sizes as you drew them, before solves (JSON)</source>
        <translation>Quadergrößen, wie Sie sie gezeichnet haben, vor dem Lösen (JSON)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="13"/>
        <source>The axis-aligned boxes (Part::Box) the part is made of</source>
        <translation>Die achsparallelen Quader (Part::Box), aus denen das Teil besteht</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="15"/>
        <source>Boxes cut out of it: openings and compartments that can be covered or fitted into</source>
        <translation>Daraus ausgeschnittene Quader: Öffnungen und Fächer, die abgedeckt oder befüllt werden können</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="26"/>
        <source>The mechanism to print in place</source>
        <translation>Der Mechanismus, der am Stück gedruckt wird</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="28"/>
        <source>Printer profile: the gap it needs</source>
        <translation>Druckerprofil: der Spalt, den es braucht</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="30"/>
        <source>Clearance between parts (set by the printer profile)</source>
        <translation>Spiel zwischen Teilen (vom Druckerprofil gesetzt)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="33"/>
        <source>Print at this scale (0.2 for 1:5); the gap stays as it is</source>
        <translation>In diesem Maßstab drucken (0,2 für 1:5); der Spalt bleibt, wie er ist</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="35"/>
        <source>Print at the largest scale (at most 1) that fits the build volume; sets Scale</source>
        <translation>Im größten Maßstab (höchstens 1) drucken, der in den Bauraum passt; setzt Scale</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="38"/>
        <source>The printer&apos;s build volume in mm: width (x), depth (y), height (z); the print may turn a quarter about z</source>
        <translation>Der Bauraum des Druckers in mm: Breite (x), Tiefe (y), Höhe (z); der Druck darf sich um eine Vierteldrehung um z drehen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="42"/>
        <source>Width x depth x height of the print</source>
        <translation>Breite x Tiefe x Höhe des Drucks</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="44"/>
        <source>Fitted turned a quarter about z: exported so, shown as modelled</source>
        <translation>Mit einer Vierteldrehung um z eingepasst: so exportiert, wie modelliert angezeigt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="47"/>
        <source>Show the volumes swept into cavities</source>
        <translation>Die in Hohlräume überstrichenen Volumen zeigen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="49"/>
        <source>Measure the clearance at 32 poses along every configuration&apos;s motion</source>
        <translation>Das Spiel in 32 Stellungen entlang der Bewegung jeder Konfiguration messen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="52"/>
        <source>Least distance between two bodies</source>
        <translation>Kleinster Abstand zwischen zwei Körpern</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="54"/>
        <source>Where the least distance is</source>
        <translation>Wo der kleinste Abstand liegt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="56"/>
        <source>Joints made without geometry, and why</source>
        <translation>Gelenke, die ohne Geometrie erstellt wurden, und warum</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="14"/>
        <source>The configuration it must hold in; empty: as modelled</source>
        <translation>Die Konfiguration, in der sie gelten muss; leer: wie modelliert</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="16"/>
        <source>Satisfied, or what it conflicts with</source>
        <translation>Erfüllt, oder womit sie im Widerspruch steht</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="25"/>
        <source>Parts whose faces cover</source>
        <translation>Teile, deren Flächen abdecken</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="27"/>
        <source>Parts whose faces are covered</source>
        <translation>Teile, deren Flächen abgedeckt werden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="29"/>
        <source>Just cover: the covering faces no larger than the covered</source>
        <translation>Genau abdecken: die abdeckenden Flächen nicht größer als die abgedeckten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="46"/>
        <source>Parts that must fit inside</source>
        <translation>Teile, die hineinpassen müssen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="48"/>
        <source>The part they fit inside</source>
        <translation>Das Teil, in das sie passen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="50"/>
        <source>A cavity of the enclosing part to fit in; empty: its box</source>
        <translation>Ein Hohlraum des umschließenden Teils, in den sie passen; leer: sein Quader</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="52"/>
        <source>Partial fit: the boxes of the inner parts that must fit (a drawer&apos;s tray, not its front); empty: all</source>
        <translation>Teilweise Passung: die Quader der inneren Teile, die passen müssen (der Kasten einer Schublade, nicht ihre Front); leer: alle</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="59"/>
        <source>Each inner part just fits on its own along the ticked axes (stacked trays without play), not only the inner parts taken together</source>
        <translation>Jedes innere Teil passt für sich genau entlang der angehakten Achsen (gestapelte Kästen ohne Spiel), nicht nur die inneren Teile zusammen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="80"/>
        <source>Parts that support (legs, frames)</source>
        <translation>Teile, die tragen (Beine, Rahmen)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="82"/>
        <source>Parts resting on them</source>
        <translation>Teile, die darauf ruhen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="100"/>
        <source>Two box faces that lie in one plane</source>
        <translation>Zwei Quaderflächen, die in einer Ebene liegen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="120"/>
        <source>Left = or &lt;= right + offset</source>
        <translation>Links = oder &lt;= rechts + Versatz</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="125"/>
        <source>Added to the right side</source>
        <translation>Zur rechten Seite addiert</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="27"/>
        <source>Sketch, planar face or thin solid the board is made of</source>
        <translation>Skizze, ebene Fläche oder dünner Körper, aus dem die Platte besteht</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="29"/>
        <source>Thickness of a board made from a sketch or face (detected for a solid)</source>
        <translation>Dicke einer Platte aus einer Skizze oder Fläche (bei einem Körper erkannt)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="32"/>
        <source>How many to cut</source>
        <translation>Wie viele geschnitten werden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="33"/>
        <source>Turns allowed on the master board: any, keeping its length along the grain, or none</source>
        <translation>Erlaubte Drehungen auf der Rohplatte: beliebig, mit der Länge entlang der Maserung, oder keine</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="43"/>
        <source>Longest side of the outline&apos;s box</source>
        <translation>Längste Seite des Umrissrechtecks</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="45"/>
        <source>Other side of the outline&apos;s box</source>
        <translation>Andere Seite des Umrissrechtecks</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="36"/>
        <source>Master boards to cut the boards from</source>
        <translation>Rohplatten, aus denen die Platten geschnitten werden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="38"/>
        <source>Grid cell size tau (thesis 5.4.1)</source>
        <translation>Rasterzellgröße tau (Dissertation 5.4.1)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="40"/>
        <source>Width of the cut</source>
        <translation>Breite des Schnitts</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="41"/>
        <source>Extra material between parts</source>
        <translation>Zusätzliches Material zwischen Teilen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="43"/>
        <source>Margin cut off every master board edge</source>
        <translation>Rand, der an jeder Kante der Rohplatte abgeschnitten wird</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="48"/>
        <source>Boards that touch stay touching (edge snapping)</source>
        <translation>Platten, die sich berühren, bleiben in Berührung (Kantenfang)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="50"/>
        <source>How many times its length now Suggest may make a board&apos;s side (1.5: half as long again), so a batten stays a batten; your own edits are not held</source>
        <translation>Wie viel Mal ihre jetzige Länge Vorschlagen die Seite einer Platte machen darf (1,5: um die Hälfte länger), damit eine Leiste eine Leiste bleibt; Ihre eigenen Änderungen sind nicht begrenzt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="54"/>
        <source>A box you edit keeps its new size and place while the rest adapts to the constraints</source>
        <translation>Ein Quader, den Sie ändern, behält seine neue Größe und Lage, während sich der Rest den Vorgaben anpasst</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="57"/>
        <source>Spreadsheet aliases that drive the boxes by expressions, as &apos;Sheet.alias min max&apos; (thesis 5.4.2.2); when given, Suggest changes these instead of the boxes</source>
        <translation>Tabellen-Aliase, die die Quader über Ausdrücke steuern, als 'Sheet.alias min max' (Dissertation 5.4.2.2); sind sie angegeben, ändert Vorschlagen diese statt der Quader</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="61"/>
        <source>Part area / layout bounding rectangle (thesis 5.2.3)</source>
        <translation>Teilefläche / umschließendes Rechteck des Layouts (Dissertation 5.2.3)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="64"/>
        <source>Laid out, or what is wrong</source>
        <translation>Ausgelegt, oder was nicht stimmt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="66"/>
        <source>What the last recompute or accepted suggestion that moved boards did: size old → new, how far</source>
        <translation>Was die letzte Neuberechnung oder der letzte übernommene Vorschlag, der Platten bewegte, getan hat: Größe alt → neu, wie weit</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="70"/>
        <source>Boards after the last valid recompute (JSON)</source>
        <translation>Platten nach der letzten gültigen Neuberechnung (JSON)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="99"/>
        <source>What must hold</source>
        <translation>Was gelten muss</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="106"/>
        <source>Boxes for ground, coplanar and snap</source>
        <translation>Quader für Boden, koplanar und Fang</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="108"/>
        <source>Fixed value or sum offset</source>
        <translation>Fester Wert oder Versatz der Summe</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="110"/>
        <source>Range: smallest value (beyond ±10⁸ m: none)</source>
        <translation>Bereich: kleinster Wert (jenseits ±10⁸ m: keiner)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="113"/>
        <source>Range: largest value (beyond ±10⁸ m: none)</source>
        <translation>Bereich: größter Wert (jenseits ±10⁸ m: keiner)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="118"/>
        <source>Satisfied, or what breaks it</source>
        <translation>Erfüllt, oder was sie verletzt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="136"/>
        <source>Inner: kept free; Outer: the design stays inside</source>
        <translation>Innen: bleibt frei; Außen: der Entwurf bleibt darin</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="139"/>
        <source>Inner volume: the board it rests on and moves with</source>
        <translation>Innenraum: die Platte, auf der er steht und mit der er sich bewegt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="141"/>
        <source>Size along x</source>
        <translation>Größe entlang x</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="142"/>
        <source>Size along y</source>
        <translation>Größe entlang y</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="143"/>
        <source>Size along z</source>
        <translation>Größe entlang z</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="144"/>
        <source>Satisfied, or the boards that break it</source>
        <translation>Erfüllt, oder die Platten, die sie verletzen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="211"/>
        <source>The model axis the wood&apos;s grain runs along, one in the board&apos;s face: the board is laid with it along the grain of master boards that have one. Free: no grain</source>
        <translation>Die Modellachse, entlang der die Holzmaserung verläuft, eine in der Fläche der Platte: die Platte wird damit entlang der Maserung von Rohplatten gelegt, die eine haben. Frei: keine Maserung</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="39"/>
        <source>Boards to lay out</source>
        <translation>Auszulegende Platten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="40"/>
        <source>Master boards to cut them from, opened in this order</source>
        <translation>Rohplatten, aus denen sie geschnitten werden, in dieser Reihenfolge angebrochen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="42"/>
        <source>Width of the cut (laser beam, router bit)</source>
        <translation>Breite des Schnitts (Laserstrahl, Fräser)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="45"/>
        <source>Material left between parts besides the kerf</source>
        <translation>Material, das zusätzlich zur Schnittbreite zwischen den Teilen bleibt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="48"/>
        <source>Margin kept along every master board edge</source>
        <translation>Rand, der an jeder Kante der Rohplatte frei bleibt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="51"/>
        <source>Router bit diameter: the cut sheets relieve inside corners (slots, notches) so the bit cuts them square; 0 for none (a laser)</source>
        <translation>Fräserdurchmesser: die Zuschnittpläne geben Innenecken (Schlitze, Kerben) frei, damit der Fräser sie rechtwinklig schneidet; 0 für keine (ein Laser)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="54"/>
        <source>Holding tabs left in the outer cut of small parts so they stay in the sheet; 0 for none</source>
        <translation>Haltestege im Außenschnitt kleiner Teile, damit sie in der Platte bleiben; 0 für keine</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="57"/>
        <source>Parts whose longer side is shorter get holding tabs</source>
        <translation>Teile, deren längere Seite kürzer ist, erhalten Haltestege</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="64"/>
        <source>Export the parts&apos; outlines as designed (no kerf offset, no dogbones, closed, holding tabs on a layer of their own) for CAM software that offsets by its tool itself; off: tool paths as a laser or the machine cuts them</source>
        <translation>Die Umrisse der Teile wie konstruiert exportieren (kein Versatz um die Schnittbreite, keine Dogbones, geschlossen, Haltestege auf einer eigenen Ebene) für CAM-Software, die selbst um ihr Werkzeug versetzt; aus: Werkzeugbahnen, wie ein Laser oder die Maschine sie schneidet</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="69"/>
        <source>Labels as text in a font; off: as single strokes to engrave, which laser software, CAM and FreeCAD&apos;s DXF import take as they are</source>
        <translation>Beschriftungen als Text in einer Schrift; aus: als einzelne Striche zum Gravieren, die Laser-Software, CAM und FreeCADs DXF-Import unverändert übernehmen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="72"/>
        <source>Width of the label printer&apos;s labels</source>
        <translation>Breite der Etiketten des Etikettendruckers</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="74"/>
        <source>Height of the label printer&apos;s labels</source>
        <translation>Höhe der Etiketten des Etikettendruckers</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="76"/>
        <source>Connectors where boards meet: finger joints or cross slots; dowels for boards of 18 mm or more under Auto</source>
        <translation>Verbinder, wo Platten aufeinandertreffen: Fingerzinken oder Kreuzschlitze; Dübel für Platten ab 18 mm unter Auto</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="79"/>
        <source>Free: any outline (a CNC router or laser follows it); Guillotine: straight cuts from edge to edge only (a panel, track or table saw), with the cut sequence on the cut sheets</source>
        <translation>Frei: jeder Umriss (eine CNC-Fräse oder ein Laser folgt ihm); Guillotine: nur gerade Schnitte von Kante zu Kante (Plattensäge, Tauchsäge oder Tischkreissäge), mit der Schnittfolge auf den Zuschnittplänen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="83"/>
        <source>Guillotine cuts: at most this many changes of direction (2, 3, ...); 0 = unlimited</source>
        <translation>Guillotineschnitte: höchstens so viele Richtungswechsel (2, 3, ...); 0 = unbegrenzt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="86"/>
        <source>Guillotine cuts: the first cuts along the sheet&apos;s length (x), across it, or whichever wastes less</source>
        <translation>Guillotineschnitte: die ersten Schnitte längs der Platte (x), quer dazu oder wie es weniger Verschnitt gibt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="90"/>
        <source>The connectors made</source>
        <translation>Die erstellten Verbinder</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="92"/>
        <source>Guillotine cuts: the saw cuts to make</source>
        <translation>Guillotineschnitte: die auszuführenden Sägeschnitte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="94"/>
        <source>Guillotine cuts: their total length</source>
        <translation>Guillotineschnitte: ihre Gesamtlänge</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="103"/>
        <source>Cell size of the layout grid (thesis 5.4.1)</source>
        <translation>Zellgröße des Layout-Rasters (Dissertation 5.4.1)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="105"/>
        <source>Free rotation: boards without grain may turn by every multiple of this many degrees (a divisor of 90, e.g. 15); 0 = quarter turns only</source>
        <translation>Freie Drehung: Platten ohne Maserung dürfen sich um jedes Vielfache so vieler Grad drehen (ein Teiler von 90, z. B. 15); 0 = nur Vierteldrehungen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="108"/>
        <source>Ordering swaps tried; -1 = parts squared (thesis 5.4.3)</source>
        <translation>Versuchte Vertauschungen der Reihenfolge; -1 = Teilezahl zum Quadrat (Dissertation 5.4.3)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="110"/>
        <source>Seed of the ordering search</source>
        <translation>Startwert der Reihenfolgesuche</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="112"/>
        <source>Seconds the search may take at most; in FreeCAD a dialog shows it and Stop keeps the best layout so far</source>
        <translation>Sekunden, die die Suche höchstens dauern darf; in FreeCAD zeigt ein Dialog sie an, und Stopp behält das bisher beste Layout</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="116"/>
        <source>Part area / bounding rectangle of the layout</source>
        <translation>Teilefläche / umschließendes Rechteck des Layouts</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="118"/>
        <source>Part area / area of the master boards used</source>
        <translation>Teilefläche / Fläche der benutzten Rohplatten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="121"/>
        <source>Area of the master boards used minus part area</source>
        <translation>Fläche der benutzten Rohplatten minus Teilefläche</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="123"/>
        <source>Master boards used</source>
        <translation>Benutzte Rohplatten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="125"/>
        <source>The problem laid out (*.pack.json)</source>
        <translation>Die ausgelegte Aufgabe (*.pack.json)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="127"/>
        <source>The layout (layout JSON)</source>
        <translation>Das Layout (Layout-JSON)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="17"/>
        <source>Size along the layout&apos;s x axis</source>
        <translation>Größe entlang der x-Achse des Layouts</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="19"/>
        <source>Size along the layout&apos;s y axis</source>
        <translation>Größe entlang der y-Achse des Layouts</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="21"/>
        <source>Material thickness</source>
        <translation>Materialdicke</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="23"/>
        <source>Boards in stock; 0 = as many as needed</source>
        <translation>Platten auf Lager; 0 = so viele wie nötig</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="25"/>
        <source>Material name for the cut list</source>
        <translation>Materialname für die Zuschnittliste</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="27"/>
        <source>Direction of the wood grain; boards set to Follow grain keep their length along it</source>
        <translation>Richtung der Holzmaserung; Platten mit Follow grain behalten ihre Länge entlang ihr</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="30"/>
        <source>What one board costs (any unit; 1 = a sheet); 0 for an offcut you have, which is used before new sheets</source>
        <translation>Was eine Platte kostet (beliebige Einheit; 1 = eine Platte); 0 für einen vorhandenen Rest, der vor neuen Platten verwendet wird</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="111"/>
        <source>Why the last recompute failed; empty when it did not</source>
        <translation>Warum die letzte Neuberechnung fehlschlug; leer, wenn nicht</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="55"/>
        <source>Just fits in width (along X)</source>
        <translation>Passt genau in der Breite (entlang X)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="55"/>
        <source>Just fits in depth (along Y)</source>
        <translation>Passt genau in der Tiefe (entlang Y)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="55"/>
        <source>Just fits in height (along Z)</source>
        <translation>Passt genau in der Höhe (entlang Z)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="36"/>
        <source>Band glued on its first long edge (e.g. &apos;oak 1 mm&apos;); empty: none</source>
        <translation>Umleimer auf der ersten langen Kante (z. B. 'Eiche 1 mm'); leer: keiner</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="36"/>
        <source>Band glued on its second long edge (e.g. &apos;oak 1 mm&apos;); empty: none</source>
        <translation>Umleimer auf der zweiten langen Kante (z. B. 'Eiche 1 mm'); leer: keiner</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="36"/>
        <source>Band glued on its first short edge (e.g. &apos;oak 1 mm&apos;); empty: none</source>
        <translation>Umleimer auf der ersten kurzen Kante (z. B. 'Eiche 1 mm'); leer: keiner</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="36"/>
        <source>Band glued on its second short edge (e.g. &apos;oak 1 mm&apos;); empty: none</source>
        <translation>Umleimer auf der zweiten kurzen Kante (z. B. 'Eiche 1 mm'); leer: keiner</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="60"/>
        <source>Common-line cutting: a line two boards a kerf apart share is cut once, by the board cut first (Spacing 0 lays boards so); the machine&apos;s paths only, not AsDesigned</source>
        <translation>Gemeinsamer Schnitt: eine Linie, die zwei eine Schnittbreite auseinanderliegende Platten teilen, wird einmal geschnitten, mit der zuerst geschnittenen Platte (Spacing 0 legt Platten so); nur für die Bahnen der Maschine, nicht AsDesigned</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="96"/>
        <source>Length of all cuts: the saw&apos;s for guillotine cuts, else every outline and hole, a line two boards share counted once with CommonLine</source>
        <translation>Länge aller Schnitte: bei Guillotineschnitten die der Säge, sonst alle Umrisse und Löcher, eine Linie, die zwei Platten teilen, mit CommonLine einmal gezählt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="100"/>
        <source>CommonLine: the length of the lines two boards share, cut once</source>
        <translation>CommonLine: die Länge der Linien, die zwei Platten teilen, einmal geschnitten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="49"/>
        <source>How far the joint turns its part (right-handed about its edge&apos;s +x/+y/+z direction)</source>
        <translation>Wie weit das Gelenk sein Teil dreht (rechtshändig um die +x/+y/+z-Richtung seiner Kante)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="52"/>
        <source>How far the joint slides its part</source>
        <translation>Wie weit das Gelenk sein Teil verschiebt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="35"/>
        <source>Coordinates that keep their value: a box and its side</source>
        <translation>Koordinaten, die ihren Wert behalten: ein Quader und seine Seite</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="158"/>
        <source>The body this shape is</source>
        <translation>Der Körper, den diese Form darstellt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="31"/>
        <source>Corresponding faces, two by two: &apos;covering -&gt; covered&apos; (thesis 4.3.1); empty: inferred on the next solve</source>
        <translation>Zugehörige Flächen, paarweise: 'abdeckend -&gt; abgedeckt' (Dissertation 4.3.1); leer: beim nächsten Lösen abgeleitet</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="31"/>
        <source>How far apart faces may be to correspond when inferring the pairs</source>
        <translation>Wie weit Flächen auseinander liegen dürfen, um beim Ableiten der Paare zusammenzugehören</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="84"/>
        <source>Corresponding faces, two by two: &apos;supporting top -&gt; supported bottom&apos; (thesis 4.3.3); empty: inferred on the next solve</source>
        <translation>Zugehörige Flächen, paarweise: 'tragende Oberseite -&gt; getragene Unterseite' (Dissertation 4.3.3); leer: beim nächsten Lösen abgeleitet</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="84"/>
        <source>How far above a top face a bottom face may be when inferring the pairs</source>
        <translation>Wie weit über einer Oberseite eine Unterseite beim Ableiten der Paare liegen darf</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="115"/>
        <source>Quantities summed: a box and its side or size (width/depth/height), with a factor in front if not 1 (the formats write &apos;Door.width&apos;, &apos;2*Shelf.height&apos;, &apos;-Lid.left&apos;)</source>
        <translation>Summierte Größen: ein Quader und seine Seite oder Größe (width/depth/height), mit einem Faktor davor, wenn nicht 1 (die Formate schreiben 'Door.width', '2*Shelf.height', '-Lid.left')</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="123"/>
        <source>Quantities summed (may be empty)</source>
        <translation>Summierte Größen (darf leer sein)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="191"/>
        <source>The layout this was made from</source>
        <translation>Das Layout, aus dem dies erstellt wurde</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="101"/>
        <source>Boxes and what of them (size.x, centre.z, min.y, max.x): equal, symmetric (two), sum (left side), fixed and range (one)</source>
        <translation>Quader und was von ihnen (size.x, centre.z, min.y, max.x): gleich, symmetrisch (zwei), Summe (linke Seite), fest und Bereich (einer)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="105"/>
        <source>Right side of a sum</source>
        <translation>Rechte Seite einer Summe</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="116"/>
        <source>Symmetric about this reference (empty: midway now)</source>
        <translation>Symmetrisch zu dieser Referenz (leer: jetzige Mitte)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="34"/>
        <source>The designs and layouts cut from this master board: a change reaches them all</source>
        <translation>Die Entwürfe und Layouts, die aus dieser Rohplatte geschnitten werden: eine Änderung erreicht sie alle</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/techdraw.py" line="62"/>
        <source>The layout this page draws</source>
        <translation>Das Layout, das diese Seite zeichnet</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="38"/>
        <source>The FabGuide version that wrote this</source>
        <translation>Die FabGuide-Version, die dies geschrieben hat</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="45"/>
        <source>Shortest side a board may shrink to; 0: twice each board&apos;s own thickness, as a file without min_length</source>
        <translation>Kürzeste Seite, auf die eine Platte schrumpfen darf; 0: die doppelte Dicke jeder Platte, wie in einer Datei ohne min_length</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="72"/>
        <source>The last layout, its problem and the design it was made from (JSON)</source>
        <translation>Das letzte Layout, seine Aufgabe und der Entwurf, aus dem es entstand (JSON)</translation>
    </message>
</context>
<context>
    <name>CamJobPanel</name>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="6"/>
        <source>Make CAM Job</source>
        <translation>CAM-Job erstellen</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="12"/>
        <source>One CAM job per master board: the sheet as stock, the parts as solids, profiles from their outlines as designed (the tool&apos;s radius is CAM&apos;s), holding tags, dogbones, dowel drilling and engraved labels as the layout asks.</source>
        <translation>Ein CAM-Job je Rohplatte: die Platte als Rohteil, die Teile als Körper, Konturen aus ihren Umrissen wie konstruiert (den Werkzeugradius rechnet CAM), Haltestege, Dogbones, Dübelbohrungen und gravierte Beschriftungen, wie das Layout sie verlangt.</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="17"/>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="19"/>
        <source>Tool bit</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="19"/>
        <source>The end mill that profiles the parts (a FreeCAD tool bit file, *.fctb)</source>
        <translation>Der Schaftfräser, der die Teile ausfräst (eine FreeCAD-Werkzeugdatei, *.fctb)</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="23"/>
        <source>Other…</source>
        <translation>Andere…</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="26"/>
        <source>Post-processor</source>
        <translation>Postprozessor</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="26"/>
        <source>The G-code dialect of your machine&apos;s controller</source>
        <translation>Der G-Code-Dialekt Ihrer Maschinensteuerung</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="28"/>
        <source>Per material</source>
        <translation>Je Material</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="28"/>
        <source>The feed across the sheet and the spindle speed for each material of the layout&apos;s master boards (remembered for the next job)</source>
        <translation>Vorschub und Spindeldrehzahl für jedes Material der Rohplatten des Layouts (für den nächsten Job gemerkt)</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="40"/>
        <source>Cut through by</source>
        <translation>Durchschneiden um</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="40"/>
        <source>How far the profiles cut below the sheet, into the spoilboard, so that the parts come free (0: to the sheet&apos;s underside)</source>
        <translation>Wie tief die Konturen unter die Platte in die Opferplatte schneiden, damit die Teile frei werden (0: bis zur Unterseite der Platte)</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="41"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="47"/>
        <source>Write G-code</source>
        <translation>G-Code schreiben</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="52"/>
        <source>Folder…</source>
        <translation>Ordner…</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="34"/>
        <source>Feed
mm/min</source>
        <translation>Vorschub
mm/min</translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="36"/>
        <source>Spindle
rpm</source>
        <translation>Spindel
U/min</translation>
    </message>
</context>
<context>
    <name>ConfigurationsPanel</name>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="6"/>
        <source>Configurations</source>
        <translation>Konfigurationen</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="11"/>
        <source>Configuration</source>
        <translation>Konfiguration</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="13"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="19"/>
        <source>Joints it poses</source>
        <translation>Gelenke, die sie stellt</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="20"/>
        <source>Tick the joints this configuration poses; an angle&apos;s sign is the way the part swings</source>
        <translation>Haken Sie die Gelenke an, die diese Konfiguration stellt; das Vorzeichen eines Winkels gibt an, wohin das Teil schwenkt</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="26"/>
        <source>Move the mechanism from its base pose to the configuration, the way the print moves: turns first, then slides</source>
        <translation>Den Mechanismus aus seiner Grundstellung in die Konfiguration bewegen, so wie sich der Druck bewegt: erst Drehungen, dann Schübe</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="34"/>
        <source>Base</source>
        <translation>Grundstellung</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="34"/>
        <source>The left end of the slider: the base pose</source>
        <translation>Das linke Ende des Schiebers: die Grundstellung</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="35"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="36"/>
        <source>Posed</source>
        <translation>Gestellt</translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="36"/>
        <source>The right end of the slider: the configuration</source>
        <translation>Das rechte Ende des Schiebers: die Konfiguration</translation>
    </message>
</context>
<context>
    <name>FabGuide</name>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="22"/>
        <source>&apos;{}&apos; is rotated: FabGuide parts are axis-aligned boxes (reset its Placement rotation; joints turn parts in configurations)</source>
        <translation>'{}' ist gedreht: FabGuide-Teile sind achsparallele Quader (setzen Sie die Drehung seiner Placement zurück; Gelenke drehen Teile in Konfigurationen)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="28"/>
        <source>&apos;{}&apos;: its Length, Width, Height and Placement must be finite numbers</source>
        <translation>'{}': Length, Width, Height und Placement müssen endliche Zahlen sein</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="76"/>
        <source>&apos;{}.{}&apos; is not a face of the box</source>
        <translation>'{}.{}' ist keine Fläche des Quaders</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="95"/>
        <source>&apos;{}.{}&apos; is not an edge of the box</source>
        <translation>'{}.{}' ist keine Kante des Quaders</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="104"/>
        <source>&apos;{}&apos; has no edge between its {} and {} faces</source>
        <translation>'{}' hat keine Kante zwischen seinen Flächen {} und {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="98"/>
        <source>Configuration &apos;{}&apos;: &apos;{}&apos; is not a joint</source>
        <translation>Konfiguration '{}': '{}' ist kein Gelenk</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="116"/>
        <source>Joint &apos;{}&apos;: choose the Part it moves</source>
        <translation>Gelenk '{}': wählen Sie das Teil (Part), das es bewegt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="122"/>
        <source>Joint &apos;{}&apos;: choose the Edge it turns about</source>
        <translation>Gelenk '{}': wählen Sie die Kante (Edge), um die es dreht</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="125"/>
        <source>Joint &apos;{}&apos;: its edge is on &apos;{}&apos;, which is not a box of part &apos;{}&apos;</source>
        <translation>Gelenk '{}': seine Kante liegt auf '{}', das kein Quader des Teils '{}' ist</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="130"/>
        <source>Joint &apos;{}&apos;: {}</source>
        <translation>Gelenk '{}': {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="134"/>
        <source>Fixed joint &apos;{}&apos;: choose the Base part it holds &apos;{}&apos; to</source>
        <translation>Festes Gelenk '{}': wählen Sie das Basisteil (Base), an dem es '{}' hält</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="138"/>
        <source>Double pivot &apos;{}&apos;: choose the Base part it links to</source>
        <translation>Doppelgelenk '{}': wählen Sie das Basisteil (Base), mit dem es verbindet</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="143"/>
        <source>Double pivot &apos;{}&apos;: choose a face of a box of &apos;{}&apos; for its {}</source>
        <translation>Doppelgelenk '{}': wählen Sie eine Fläche eines Quaders von '{}' für {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="178"/>
        <source>Mechanism &apos;{}&apos;: {}</source>
        <translation>Mechanismus '{}': {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="201"/>
        <source>{}: these cannot hold together: {}. {}
</source>
        <translation>{}: diese können nicht zugleich gelten: {}. {}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="39"/>
        <source>Part &apos;{}&apos; has no boxes: add a Part::Box to its Cuboids</source>
        <translation>Teil '{}' hat keine Quader: fügen Sie seinen Cuboids eine Part::Box hinzu</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="44"/>
        <source>Part &apos;{}&apos;: &apos;{}&apos; is not a Part::Box</source>
        <translation>Teil '{}': '{}' ist keine Part::Box</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="71"/>
        <source>Printable &apos;{}&apos;: the mechanism has new parts ({}); run Make Printable again</source>
        <translation>Druckteil '{}': der Mechanismus hat neue Teile ({}); führen Sie Druckbar machen erneut aus</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="92"/>
        <source>Printable &apos;{}&apos;: invalid solids: {}</source>
        <translation>Druckteil '{}': ungültige Körper: {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="95"/>
        <source>Printable &apos;{}&apos;: bodies that print in pieces ({}): a cut went through them, a joint turning the wrong way round or a part in the way</source>
        <translation>Druckteil '{}': Körper, die in Stücken gedruckt würden ({}): ein Schnitt ging durch sie hindurch, ein Gelenk dreht falsch herum oder ein Teil steht im Weg</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="100"/>
        <source>{}: parts come within {:.3f} mm of each other ({}), less than the {} mm gap
</source>
        <translation>{}: Teile kommen sich bis auf {:.3f} mm nahe ({}), weniger als der Spalt von {} mm
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="116"/>
        <source>Printable &apos;{}&apos;: choose the Mechanism to print</source>
        <translation>Druckteil '{}': wählen Sie den Mechanismus, der gedruckt werden soll</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="122"/>
        <source>Printable &apos;{}&apos;: {}</source>
        <translation>Druckteil '{}': {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="132"/>
        <source>Printable &apos;{}&apos;: BuildVolume must be greater than 0 in x, y and z (is {:g} x {:g} x {:g})</source>
        <translation>Druckteil '{}': BuildVolume muss in x, y und z größer als 0 sein (ist {:g} x {:g} x {:g})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="177"/>
        <source>Printable &apos;{}&apos;: {}; mend that first</source>
        <translation>Druckteil '{}': {}; beheben Sie das zuerst</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="181"/>
        <source>Printable &apos;{}&apos;: not made from the mechanism as it stands ({} changed); recompute first</source>
        <translation>Druckteil '{}': nicht aus dem Mechanismus, wie er jetzt ist, erstellt ({} geändert); erst neu berechnen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="187"/>
        <source>Printable &apos;{}&apos;: {} not made yet; recompute it first</source>
        <translation>Druckteil '{}': {} noch nicht erstellt; erst neu berechnen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="65"/>
        <source>Fit inside &apos;{}&apos;: choose the Enclosing part</source>
        <translation>Passt hinein '{}': wählen Sie das umschließende Teil (Enclosing)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="106"/>
        <source>Flush &apos;{}&apos;: choose exactly two faces, got {}</source>
        <translation>Bündig '{}': wählen Sie genau zwei Flächen, gewählt sind {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="146"/>
        <source>Geometric &apos;{}&apos;: &apos;{}&apos; must read &apos;Box.side&apos;, &apos;Box.width&apos; or &apos;factor*Box.width&apos;</source>
        <translation>Geometrisch '{}': '{}' muss 'Box.side', 'Box.width' oder 'factor*Box.width' lauten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="168"/>
        <source>{} &apos;{}&apos;: its Pairs lost a face (a box was deleted?); re-infer them (clear Pairs) or correct them</source>
        <translation>{} '{}': seinen Pairs fehlt eine Fläche (ein Quader gelöscht?); leiten Sie sie neu ab (Pairs leeren) oder korrigieren Sie sie</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="216"/>
        <source>{} &apos;{}&apos;: pair &apos;{}&apos; must read &apos;Box.side -&gt; Box.side&apos;</source>
        <translation>{} '{}': Paar '{}' muss 'Box.side -&gt; Box.side' lauten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="154"/>
        <source>Build FabGuide&apos;s core</source>
        <translation>FabGuides Kern bauen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="125"/>
        <source>Cancelled: nothing was installed.</source>
        <translation>Abgebrochen: nichts wurde installiert.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="133"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="152"/>
        <source>FabGuide: the core cannot be built: {}.
</source>
        <translation>FabGuide: der Kern kann nicht gebaut werden: {}.
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="154"/>
        <source>The core cannot be built: {}.</source>
        <translation>Der Kern kann nicht gebaut werden: {}.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/command_base.py" line="31"/>
        <source>FabGuide</source>
        <translation>FabGuide</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="94"/>
        <source>&lt;b&gt;No CAM job made:&lt;/b&gt; {}</source>
        <translation>&lt;b&gt;Kein CAM-Job erstellt:&lt;/b&gt; {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/command_base.py" line="30"/>
        <source>FabGuide: {}
</source>
        <translation>FabGuide: {}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="99"/>
        <source>FabGuide: {} CAM job(s) for &apos;{}&apos;{}
</source>
        <translation>FabGuide: {} CAM-Job(s) für '{}'{}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/command_base.py" line="144"/>
        <source>{}: cannot use &apos;{}&apos;: {}.</source>
        <translation>{}: '{}' kann nicht verwendet werden: {}.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/command_base.py" line="156"/>
        <source>{} did not finish: {} ({}). Please report this, with what you did, at the FabGuide issue tracker.</source>
        <translation>{} wurde nicht beendet: {} ({}). Bitte melden Sie das mit Ihren Schritten im Issue-Tracker von FabGuide.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="33"/>
        <source>Make a mechanism, a part or a cavity from boxes</source>
        <translation>Einen Mechanismus, ein Teil oder einen Hohlraum aus Quadern erstellen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="35"/>
        <source>Add a joint: hinge, slide, sliding hinge, double pivot or fixed</source>
        <translation>Ein Gelenk hinzufügen: Scharnier, Schiene, Schiebescharnier, Doppelgelenk oder fest</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="37"/>
        <source>Add a relationship: cover, fit inside, support, flush or geometric</source>
        <translation>Eine Beziehung hinzufügen: abdecken, einpassen, stützen, bündig oder geometrisch</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="39"/>
        <source>Make the mechanism printable in place, or export the print</source>
        <translation>Den Mechanismus in einem Stück druckbar machen oder den Druck exportieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="41"/>
        <source>Import or export a *.workslike.json model</source>
        <translation>Ein *.workslike.json-Modell importieren oder exportieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="43"/>
        <source>Make boards from thin solids, or from a sketch or face; band their edges</source>
        <translation>Platten aus dünnen Körpern, einer Skizze oder einer Fläche erstellen; ihre Kanten bekanten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="45"/>
        <source>Export cut sheets, make TechDraw pages or CAM jobs</source>
        <translation>Zuschnittpläne exportieren, TechDraw-Seiten oder CAM-Jobs erstellen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="47"/>
        <source>Add a design constraint on the picked boards</source>
        <translation>Eine Entwurfsbedingung an den gewählten Platten hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="49"/>
        <source>Add an inner (kept free) or the outer volume</source>
        <translation>Ein inneres (frei gehaltenes) oder das äußere Volumen hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="51"/>
        <source>Import or export a *.flatpack.json design</source>
        <translation>Einen *.flatpack.json-Entwurf importieren oder exportieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="57"/>
        <source>Angle: its sign is the way the part swings</source>
        <translation>Winkel: sein Vorzeichen gibt an, wohin das Teil schwenkt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="58"/>
        <source>Offset along the slide</source>
        <translation>Verschiebung entlang der Führung</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="122"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="125"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="51"/>
        <source>Pick boxes of one flat-pack design (use Flat-pack Design from Boxes first).</source>
        <translation>Wählen Sie Quader eines Flachpaket-Entwurfs (zuerst „Flachpaket-Entwurf aus Quadern“ verwenden).</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="66"/>
        <source>{} does not hold for the design as it is: {}</source>
        <translation>{} gilt für den Entwurf in seinem jetzigen Zustand nicht: {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="78"/>
        <source>Flat-pack Design from Boxes</source>
        <translation>Flachpaket-Entwurf aus Quadern</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="88"/>
        <source>Select the Part boxes your furniture is made of first.</source>
        <translation>Wählen Sie zuerst die Part-Quader, aus denen Ihr Möbel besteht.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="105"/>
        <source>Import Flat-pack Design</source>
        <translation>Flachpaket-Entwurf importieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="106"/>
        <source>Open a *.flatpack.json design: boxes, master boards, constraints and volumes</source>
        <translation>Einen *.flatpack.json-Entwurf öffnen: Quader, Rohplatten, Bedingungen und Volumen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="118"/>
        <source>Cannot import {}: {}</source>
        <translation>{} kann nicht importiert werden: {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="137"/>
        <source>Export Flat-pack Design</source>
        <translation>Flachpaket-Entwurf exportieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="138"/>
        <source>Write the selected design as *.flatpack.json (for `fabguide optimise` and bug reports)</source>
        <translation>Den gewählten Entwurf als *.flatpack.json schreiben (für `fabguide optimise` und Fehlerberichte)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="168"/>
        <source>Pick an edge of a box for {}.</source>
        <translation>Wählen Sie eine Kante eines Quaders für {}.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="168"/>
        <source>Pick edges of boxes for {}.</source>
        <translation>Wählen Sie Kanten von Quadern für {}.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="178"/>
        <source>Equal Lengths</source>
        <translation>Gleiche Längen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="179"/>
        <source>The picked edges of boards keep equal lengths</source>
        <translation>Die gewählten Plattenkanten behalten gleiche Längen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="183"/>
        <source>Sum of Lengths</source>
        <translation>Summe der Längen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="184"/>
        <source>The lengths of the picked edges add up to the length of the last one picked</source>
        <translation>Die Längen der gewählten Kanten ergeben zusammen die Länge der zuletzt gewählten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="192"/>
        <source>Fixed Length</source>
        <translation>Feste Länge</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="193"/>
        <source>Each picked edge keeps its present length</source>
        <translation>Jede gewählte Kante behält ihre jetzige Länge</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="202"/>
        <source>Length Range</source>
        <translation>Längenbereich</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="203"/>
        <source>Each picked edge may change by at most 25 % (edit Min and Max of the constraint)</source>
        <translation>Jede gewählte Kante darf sich um höchstens 25 % ändern (Min und Max der Bedingung bearbeiten)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="213"/>
        <source>Equal Position</source>
        <translation>Gleiche Position</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="214"/>
        <source>The picked faces of boards stay level with each other (same coordinate along their normal)</source>
        <translation>Die gewählten Plattenflächen bleiben auf einer Höhe (gleiche Koordinate entlang ihrer Normalen)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="222"/>
        <source>Pick two or more parallel faces of boards for Equal Position.</source>
        <translation>Wählen Sie zwei oder mehr parallele Plattenflächen für „Gleiche Position“.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="238"/>
        <source>Pick {} for {}.</source>
        <translation>Wählen Sie {} für {}.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="246"/>
        <source>Ground Touching</source>
        <translation>Auf dem Boden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="247"/>
        <source>The picked boards keep standing on the ground (their lowest face at the lowest board&apos;s level)</source>
        <translation>Die gewählten Platten bleiben auf dem Boden stehen (ihre unterste Fläche auf der Höhe der untersten Platte)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="252"/>
        <source>Coplanar</source>
        <translation>Koplanar</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="253"/>
        <source>The picked parallel boards stay in one plane</source>
        <translation>Die gewählten parallelen Platten bleiben in einer Ebene</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="258"/>
        <source>Snap</source>
        <translation>Anliegen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="259"/>
        <source>Two touching boards stay touching, flush where they are flush (designs snap all contacts by default)</source>
        <translation>Zwei sich berührende Platten bleiben in Kontakt und bündig, wo sie bündig sind (Entwürfe halten standardmäßig alle Kontakte)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="265"/>
        <source>Symmetric</source>
        <translation>Symmetrisch</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="266"/>
        <source>Two boards stay mirror images about the plane midway between them (along the axis that separates them)</source>
        <translation>Zwei Platten bleiben spiegelbildlich zur Ebene in ihrer Mitte (entlang der Achse, die sie trennt)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="286"/>
        <source>Inner Volume</source>
        <translation>Inneres Volumen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="287"/>
        <source>Space that must stay free, resting on the picked board (a shelf for binders); edit its size and place</source>
        <translation>Raum, der frei bleiben muss, auf der gewählten Platte (ein Fach für Ordner); Größe und Lage bearbeiten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="294"/>
        <source>Pick the one board the free space rests on.</source>
        <translation>Wählen Sie die eine Platte, auf der der freie Raum liegt.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="305"/>
        <source>Outer Volume</source>
        <translation>Äußeres Volumen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="306"/>
        <source>An envelope the selected design must stay inside (its box now, 10 % larger); edit its size and place</source>
        <translation>Eine Hülle, in der der gewählte Entwurf bleiben muss (sein jetziger Quader, 10 % größer); Größe und Lage bearbeiten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="316"/>
        <source>Design &apos;{}&apos; has no boxes to put an envelope round.</source>
        <translation>Entwurf '{}' hat keine Quader, um die eine Hülle gelegt werden kann.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="327"/>
        <source>Suggest</source>
        <translation>Vorschlagen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="328"/>
        <source>Search for design variations that keep your constraints and waste less material (or, for a design with Parameters, spreadsheet values within their ranges); preview and accept</source>
        <translation>Nach Entwurfsvarianten suchen, die Ihre Bedingungen einhalten und weniger Material verschwenden (oder, bei einem Entwurf mit Parametern, Tabellenwerte in ihren Bereichen); Vorschau und Übernehmen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/editing.py" line="44"/>
        <source>Another task panel is open: finish it with OK or Cancel first.</source>
        <translation>Ein anderer Aufgabenbereich ist offen: beenden Sie ihn zuerst mit OK oder Abbrechen.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/editing.py" line="155"/>
        <source>FabGuide: the task panel closed: its document {}
</source>
        <translation>FabGuide: das Aufgabenfenster wurde geschlossen: sein Dokument {}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="87"/>
        <source>Mechanism from Boxes</source>
        <translation>Mechanismus aus Quadern</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="88"/>
        <source>Make a mechanism; each selected box (Part::Box) becomes one of its parts</source>
        <translation>Einen Mechanismus erstellen; jeder gewählte Quader (Part::Box) wird eines seiner Teile</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="94"/>
        <source>Every picked box is already in a part: pick boxes that are not.</source>
        <translation>Jeder gewählte Quader gehört schon zu einem Teil: wählen Sie Quader, die zu keinem gehören.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="102"/>
        <source>Part from Boxes</source>
        <translation>Teil aus Quadern</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="103"/>
        <source>Make one part of the selected boxes: they move together</source>
        <translation>Ein Teil aus den gewählten Quadern erstellen: sie bewegen sich zusammen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="109"/>
        <source>Select the boxes (Part::Box) the part is made of.</source>
        <translation>Wählen Sie die Quader (Part::Box), aus denen das Teil besteht.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="119"/>
        <source>Cavity</source>
        <translation>Hohlraum</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="120"/>
        <source>Select a box of a part, then boxes to cut out of it: openings and compartments</source>
        <translation>Einen Quader eines Teils wählen, dann Quader, die daraus ausgeschnitten werden: Öffnungen und Fächer</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="127"/>
        <source>Select a box of the part first, then the boxes that are cavities in it.</source>
        <translation>Wählen Sie zuerst einen Quader des Teils, dann die Quader, die Hohlräume darin sind.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="172"/>
        <source>Pick the one edge of a box the {} turns about.</source>
        <translation>Wählen Sie die eine Kante eines Quaders, um die sich das {} dreht.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="175"/>
        <source>Pick a face of a box: the part slides along its normal.</source>
        <translation>Wählen Sie eine Fläche eines Quaders: das Teil gleitet entlang ihrer Normalen.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="191"/>
        <source>Add Hinge</source>
        <translation>Scharnier hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="192"/>
        <source>Pick an edge of a box: its part turns about it (and a box of another part it hangs on, if any)</source>
        <translation>Eine Kante eines Quaders wählen: sein Teil dreht sich um sie (und ggf. einen Quader des Teils, an dem es hängt)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="198"/>
        <source>Add Slide</source>
        <translation>Schiene hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="199"/>
        <source>Pick a face of a box: its part slides along the face&apos;s normal</source>
        <translation>Eine Fläche eines Quaders wählen: sein Teil gleitet entlang der Flächennormalen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="204"/>
        <source>Add Sliding Hinge</source>
        <translation>Schiebescharnier hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="205"/>
        <source>Pick an edge and a face of a box: its part turns about the edge, which slides along the face&apos;s normal</source>
        <translation>Eine Kante und eine Fläche eines Quaders wählen: sein Teil dreht sich um die Kante, die entlang der Flächennormalen gleitet</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="211"/>
        <source>Add Double Pivot</source>
        <translation>Doppelgelenk hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="212"/>
        <source>Pick a point on a face of the moving part&apos;s box, then one on the face of the part it links to, in the same plane: a rigid link joins them (the solve places both pivots)</source>
        <translation>Einen Punkt auf einer Fläche des Quaders des bewegten Teils wählen, dann einen auf der Fläche des verbundenen Teils, in derselben Ebene: ein starrer Lenker verbindet sie (die Lösung setzt beide Drehpunkte)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="221"/>
        <source>Pick a point on a face of the moving part&apos;s box, then one on the face of the part it links to.</source>
        <translation>Wählen Sie einen Punkt auf einer Fläche des Quaders des bewegten Teils, dann einen auf der Fläche des verbundenen Teils.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="234"/>
        <source>Add Fixed Joint</source>
        <translation>Feste Verbindung hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="235"/>
        <source>Pick a box of the part to hold, then a box of the part it rides on: it moves with that part and prints as one body with it</source>
        <translation>Einen Quader des zu haltenden Teils wählen, dann einen Quader des Teils, auf dem es sitzt: es bewegt sich mit diesem Teil und wird als ein Körper mit ihm gedruckt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="242"/>
        <source>Pick a box of the part to hold, then a box of the part it rides on.</source>
        <translation>Wählen Sie einen Quader des zu haltenden Teils, dann einen Quader des Teils, auf dem es sitzt.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="245"/>
        <source>Both boxes are in one part: pick a box of the part to hold, then one of another part.</source>
        <translation>Beide Quader gehören zu einem Teil: wählen Sie einen Quader des zu haltenden Teils, dann einen eines anderen Teils.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="248"/>
        <source>&apos;{}&apos; already rides on &apos;{}&apos;: pick the part to hold first, then the part it rides on.</source>
        <translation>'{}' sitzt schon auf '{}': wählen Sie zuerst das zu haltende Teil, dann das Teil, auf dem es sitzt.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="303"/>
        <source>Add Cover</source>
        <translation>Abdecken hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="306"/>
        <source>These parts cover that one (picked last): faces in one plane, packed, covering its faces or openings</source>
        <translation>Diese Teile decken jenes (zuletzt gewählte) ab: Flächen in einer Ebene, dicht an dicht, über seinen Flächen oder Öffnungen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="328"/>
        <source>Add Fit Inside</source>
        <translation>Einpassen hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="329"/>
        <source>These parts fit inside that one (picked last; pick one of its cavities to fit in it)</source>
        <translation>Diese Teile passen in jenes (zuletzt gewählte; einen seiner Hohlräume wählen, um in ihn einzupassen)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="342"/>
        <source>Add Support</source>
        <translation>Stützen hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="343"/>
        <source>These parts support that one (picked last): it rests on their tops; they stand on one ground</source>
        <translation>Diese Teile stützen jenes (zuletzt gewählte): es liegt auf ihren Oberseiten; sie stehen auf einem Boden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="351"/>
        <source>Add Flush</source>
        <translation>Bündig hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="352"/>
        <source>Pick two faces of boxes: they lie in one plane</source>
        <translation>Zwei Flächen von Quadern wählen: sie liegen in einer Ebene</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="368"/>
        <source>Add Geometric</source>
        <translation>Geometrisch hinzufügen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="369"/>
        <source>Pick two edges of boxes: their lengths stay equal (one edge: its length stays as it is now)</source>
        <translation>Zwei Kanten von Quadern wählen: ihre Längen bleiben gleich (eine Kante: ihre Länge bleibt wie jetzt)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="390"/>
        <source>Solve</source>
        <translation>Lösen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="391"/>
        <source>Solve the selected (or every) mechanism: the least change that makes its relationships hold</source>
        <translation>Den gewählten (oder jeden) Mechanismus lösen: die kleinste Änderung, mit der seine Beziehungen gelten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="398"/>
        <source>There is no mechanism yet: use Mechanism from Boxes first.</source>
        <translation>Es gibt noch keinen Mechanismus: verwenden Sie zuerst „Mechanismus aus Quadern“.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="408"/>
        <source>Configurations</source>
        <translation>Konfigurationen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="409"/>
        <source>Pose the joints: name configurations and move the mechanism between them</source>
        <translation>Die Gelenke stellen: Konfigurationen benennen und den Mechanismus zwischen ihnen bewegen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="422"/>
        <source>Import Works-like Model</source>
        <translation>Funktionsmodell importieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="423"/>
        <source>Build a mechanism from a *.workslike.json file</source>
        <translation>Einen Mechanismus aus einer *.workslike.json-Datei erstellen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="447"/>
        <source>Export Works-like Model</source>
        <translation>Funktionsmodell exportieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="448"/>
        <source>Write the selected mechanism as a *.workslike.json file (the CLI&apos;s fabguide solve reads it)</source>
        <translation>Den gewählten Mechanismus als *.workslike.json-Datei schreiben (die Kommandozeile liest sie mit fabguide solve)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="469"/>
        <source>Make Printable</source>
        <translation>Druckbar machen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="470"/>
        <source>Print-in-place bodies of the selected (or only) mechanism: gaps, cavities, hinge pins and yokes, pivot links; checked along every motion</source>
        <translation>In einem Stück druckbare Körper des gewählten (oder einzigen) Mechanismus: Spalte, Hohlräume, Scharnierstifte und Gabeln, Gelenklenker; entlang jeder Bewegung geprüft</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="489"/>
        <source>{}: least clearance {:.3f} mm ({})
</source>
        <translation>{}: kleinstes Spiel {:.3f} mm ({})
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="494"/>
        <source>Export Printable</source>
        <translation>Druckbares exportieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="495"/>
        <source>Write the selected printable as STL, 3MF and STEP: the assembly and one file per body</source>
        <translation>Das gewählte Druckbare als STL, 3MF und STEP schreiben: die Baugruppe und eine Datei je Körper</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="53"/>
        <source>&lt;i&gt;The layout is made again when you pause.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Das Layout wird neu erstellt, sobald Sie eine Pause machen.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="86"/>
        <source>&lt;b&gt;The layout could not be made:&lt;/b&gt; {}</source>
        <translation>&lt;b&gt;Das Layout konnte nicht erstellt werden:&lt;/b&gt; {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="27"/>
        <source>New Master Board</source>
        <translation>Neue Rohplatte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="28"/>
        <source>Add a master board (sheet size, thickness, stock, material) to cut boards from</source>
        <translation>Eine Rohplatte hinzufügen (Format, Dicke, Vorrat, Material), aus der Platten zugeschnitten werden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="41"/>
        <source>Make Board</source>
        <translation>Platte erstellen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="42"/>
        <source>Make a board from each selected sketch or planar face, as thick as the master boards</source>
        <translation>Aus jeder gewählten Skizze oder ebenen Fläche eine Platte so dick wie die Rohplatten erstellen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="50"/>
        <source>Select sketches or planar faces first.</source>
        <translation>Wählen Sie zuerst Skizzen oder ebene Flächen.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="61"/>
        <source>Boards from Solids</source>
        <translation>Platten aus Körpern</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="62"/>
        <source>Turn each selected thin solid into a board, detecting its thickness and outline</source>
        <translation>Jeden gewählten dünnen Körper in eine Platte umwandeln, Dicke und Umriss werden erkannt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="70"/>
        <source>Select the solids of your furniture model (flat boxes, pads, extrusions) first.</source>
        <translation>Wählen Sie zuerst die Körper Ihres Möbelmodells (flache Quader, Aufpolsterungen, Extrusionen).</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="96"/>
        <source>Band Edges</source>
        <translation>Kanten bekanten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="82"/>
        <source>Glue edge banding on the picked edge faces of boards (asks for the band&apos;s name; empty removes it)</source>
        <translation>Kantenband auf die gewählten Schmalflächen von Platten kleben (fragt nach dem Namen des Bands; leer entfernt es)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="94"/>
        <source>Pick the edge faces of boards (their narrow sides, not the large faces) first.</source>
        <translation>Wählen Sie zuerst Schmalflächen von Platten (ihre schmalen Seiten, nicht die großen Flächen).</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="107"/>
        <source>FabGuide: {} on {}
</source>
        <translation>FabGuide: {} auf {}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="122"/>
        <source>Nothing made: {}.</source>
        <translation>Nichts erstellt: {}.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="26"/>
        <source>Layout</source>
        <translation>Zuschnitt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="137"/>
        <source>Lay the selected (or all) boards out on the master boards and show the material usage</source>
        <translation>Die gewählten (oder alle) Platten auf den Rohplatten anordnen und die Materialausnutzung zeigen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="144"/>
        <source>There are no boards yet: use Boards from Solids or Make Board first.</source>
        <translation>Es gibt noch keine Platten: verwenden Sie zuerst „Platten aus Körpern“ oder „Platte erstellen“.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="157"/>
        <source>Export Cut Sheets</source>
        <translation>Zuschnittpläne exportieren</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="158"/>
        <source>Write SVG and DXF cut sheets per master board, a CSV cut list, the shop&apos;s PDF report and part labels for the selected layout</source>
        <translation>SVG- und DXF-Zuschnittpläne je Rohplatte, eine CSV-Stückliste, den PDF-Werkstattbericht und Teileetiketten für den gewählten Zuschnitt schreiben</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="182"/>
        <source>TechDraw Pages</source>
        <translation>TechDraw-Seiten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="183"/>
        <source>Make TechDraw pages of the selected layout&apos;s shop report: a page per master board (parts numbered and sized, grain, edge banding, saw cuts), then the cut list and the totals</source>
        <translation>TechDraw-Seiten des Werkstattberichts des gewählten Zuschnitts erstellen: eine Seite je Rohplatte (Teile nummeriert und bemaßt, Faser, Kantenband, Sägeschnitte), dann die Stückliste und die Summen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="204"/>
        <source>Make CAM Job</source>
        <translation>CAM-Job erstellen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="205"/>
        <source>Make a FreeCAD CAM job per master board of the selected layout (profiles, tags, dogbones, drilling, engraved labels) with your tool and post-processor, and write its G-code</source>
        <translation>Je Rohplatte des gewählten Zuschnitts einen FreeCAD-CAM-Job erstellen (Konturen, Haltestege, Dogbones, Bohrungen, gravierte Etiketten) mit Ihrem Werkzeug und Postprozessor, und seinen G-Code schreiben</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/relationship_panel.py" line="48"/>
        <source>&lt;b style=&apos;color:{}&apos;&gt;{}&lt;/b&gt;{}</source>
        <translation>&lt;b style='color:{}'&gt;{}&lt;/b&gt;{}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/relationship_panel.py" line="67"/>
        <source>&lt;b&gt;Pick two faces of boxes in the 3-D view&lt;/b&gt; (the first, then the second of the pair) and press Add; {} picked.</source>
        <translation>&lt;b&gt;Wählen Sie zwei Flächen von Quadern in der 3D-Ansicht&lt;/b&gt; (die erste, dann die zweite des Paars) und drücken Sie Hinzufügen; {} gewählt.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/relationship_panel.py" line="143"/>
        <source>&lt;b style=&apos;color:#b22222&apos;&gt;{}&lt;/b&gt;</source>
        <translation>&lt;b style='color:#b22222'&gt;{}&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="82"/>
        <source>Suggest cannot change {}: their sizes or places are set by expressions. Give Design &apos;{}&apos; the spreadsheet aliases that drive them as Parameters (&apos;Sheet.alias min max&apos;), and Suggest changes those.</source>
        <translation>Vorschlagen kann {} nicht ändern: ihre Größen oder Lagen werden von Ausdrücken bestimmt. Geben Sie dem Entwurf '{}' die Tabellen-Aliase, die sie steuern, als Parameters ('Sheet.alias min max'), dann ändert Vorschlagen diese.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="371"/>
        <source>Design &apos;{}&apos;: {}</source>
        <translation>Entwurf '{}': {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="349"/>
        <source>Usage now: {:.3f}</source>
        <translation>Nutzung jetzt: {:.3f}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="200"/>
        <source>Searching for designs that waste less...</source>
        <translation>Suche nach Entwürfen mit weniger Verschnitt...</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="235"/>
        <source>Searching... best usage so far {:.3f}</source>
        <translation>Suche... beste Nutzung bisher {:.3f}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="243"/>
        <source>&lt;b&gt;No suggestions:&lt;/b&gt; {}</source>
        <translation>&lt;b&gt;Keine Vorschläge:&lt;/b&gt; {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="263"/>
        <source>No variation of this design wastes less within its constraints{}{}.</source>
        <translation>Keine Variante dieses Entwurfs hat innerhalb seiner Vorgaben weniger Verschnitt{}{}.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="267"/>
        <source>{} suggestion(s) in {:.1f} s{}. Pick one; slide along its path; OK applies it.</source>
        <translation>{} Vorschlag/Vorschläge in {:.1f} s{}. Wählen Sie einen; fahren Sie seinen Pfad entlang; OK übernimmt ihn.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="285"/>
        <source>Suggestion {}: {} sheet(s) (now {}), waste {:.3f} m² (now {:.3f}), largest offcut {:.0f} x {:.0f} mm, usage {:.3f} (now {:.3f})</source>
        <translation>Vorschlag {}: {} Platte(n) (jetzt {}), Verschnitt {:.3f} m² (jetzt {:.3f}), größter Rest {:.0f} x {:.0f} mm, Nutzung {:.3f} (jetzt {:.3f})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="328"/>
        <source>usage {:.3f}</source>
        <translation>Nutzung {:.3f}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="364"/>
        <source>FabGuide: locked the size of {}
</source>
        <translation>FabGuide: die Größe von {} festgesetzt
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/workbench.py" line="12"/>
        <source>Design things that work and waste nothing: functional relationships and zero-waste layouts</source>
        <translation>Dinge entwerfen, die funktionieren und nichts verschwenden: funktionale Beziehungen und Zuschnitte ohne Verschnitt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="85"/>
        <source>Board &apos;{}&apos;: no Source (select a sketch, a planar face or a thin solid)</source>
        <translation>Platte '{}': keine Source (wählen Sie eine Skizze, eine ebene Fläche oder einen dünnen Körper)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="96"/>
        <source>{}: is FabGuide&apos;s {}, not a part of your model (pick a sketch, a planar face or a thin solid)</source>
        <translation>{}: ist FabGuides {}, kein Teil Ihres Modells (wählen Sie eine Skizze, eine ebene Fläche oder einen dünnen Körper)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="101"/>
        <source>{}: the source has no shape</source>
        <translation>{}: die Quelle hat keine Form</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="107"/>
        <source>{}: the source holds {} solids; make one board per solid</source>
        <translation>{}: die Quelle enthält {} Körper; erstellen Sie eine Platte je Körper</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="113"/>
        <source>{}: needs closed wires, a planar face or a solid</source>
        <translation>{}: braucht geschlossene Linienzüge, eine ebene Fläche oder einen Körper</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="115"/>
        <source>{}: its closed wires do not lie in one plane, so they do not outline a board</source>
        <translation>{}: seine geschlossenen Linienzüge liegen nicht in einer Ebene und umreißen daher keine Platte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="120"/>
        <source>{}: its wires do not make a planar face ({})</source>
        <translation>{}: seine Linienzüge ergeben keine ebene Fläche ({})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="126"/>
        <source>{}: the face is not planar</source>
        <translation>{}: die Fläche ist nicht eben</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="128"/>
        <source>{}: Thickness must be greater than 0</source>
        <translation>{}: Thickness muss größer als 0 sein</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="153"/>
        <source>{}: has no planar face, so it is not a flat board</source>
        <translation>{}: hat keine ebene Fläche und ist daher keine flache Platte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="158"/>
        <source>{}: no face parallel and opposite to its largest face, so it is not a flat board</source>
        <translation>{}: keine Fläche liegt seiner größten Fläche parallel gegenüber, daher ist es keine flache Platte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="163"/>
        <source>{}: is not a flat board of one thickness (volume {:.1f} mm3, face x thickness {:.1f} mm3)</source>
        <translation>{}: ist keine flache Platte einer Dicke (Volumen {:.1f} mm3, Fläche x Dicke {:.1f} mm3)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="168"/>
        <source>{}: is {:.0f} mm thick and {:.0f} mm wide, a block or a post rather than a board (a board is thinner than it is wide)</source>
        <translation>{}: ist {:.0f} mm dick und {:.0f} mm breit, eher ein Block oder Pfosten als eine Platte (eine Platte ist dünner als breit)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="52"/>
        <source>FreeCAD&apos;s CAM (Path) workbench is not installed: {}</source>
        <translation>FreeCADs CAM-Arbeitsbereich (Path) ist nicht installiert: {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="73"/>
        <source>tool bit file &apos;{}&apos; has no diameter ({})</source>
        <translation>Werkzeugdatei '{}' hat keinen Durchmesser ({})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="95"/>
        <source>no {} for the material &apos;{}&apos; (given for {})</source>
        <translation>kein(e) {} für das Material '{}' (angegeben für {})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="106"/>
        <source>cut through by {:g} mm: from 0 to 5 mm below the sheet</source>
        <translation>Durchschneiden um {:g} mm: von 0 bis 5 mm unter der Platte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="110"/>
        <source>feed {:g} mm/min for &apos;{}&apos;: from 10 to 50000 mm/min</source>
        <translation>Vorschub {:g} mm/min für '{}': von 10 bis 50000 mm/min</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="113"/>
        <source>spindle speed {:g} rpm for &apos;{}&apos;: from 0 to 60000 rpm</source>
        <translation>Spindeldrehzahl {:g} U/min für '{}': von 0 bis 60000 U/min</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="117"/>
        <source>no post-processor &apos;{}&apos; in FreeCAD (there are: {})</source>
        <translation>kein Postprozessor '{}' in FreeCAD (vorhanden sind: {})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="121"/>
        <source>tool bit file &apos;{}&apos; not found</source>
        <translation>Werkzeugdatei '{}' nicht gefunden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="124"/>
        <source>Layout &apos;{}&apos;: its parts are {:g} mm apart (Kerf {:g} + Spacing {:g} mm), too close for the {:g} mm tool: set its Kerf to the tool&apos;s diameter</source>
        <translation>Layout '{}': seine Teile liegen {:g} mm auseinander (Kerf {:g} + Spacing {:g} mm), zu eng für das {:g}-mm-Werkzeug: setzen Sie seinen Kerf auf den Werkzeugdurchmesser</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="380"/>
        <source>Job &apos;{}&apos;: post-processor &apos;{}&apos; not found</source>
        <translation>Job '{}': Postprozessor '{}' nicht gefunden</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="392"/>
        <source>Job &apos;{}&apos;: the post-processor &apos;{}&apos; wrote nothing</source>
        <translation>Job '{}': der Postprozessor '{}' hat nichts geschrieben</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="125"/>
        <source>Constraint &apos;{}&apos;: its Min ({}) is more than its Max ({})</source>
        <translation>Vorgabe '{}': ihr Min ({}) ist größer als ihr Max ({})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="157"/>
        <source>Box &apos;{}&apos; is in {} &apos;{}&apos; already, and a box belongs to one group: take it out of &apos;{}&apos; first, or pick other boxes</source>
        <translation>Quader '{}' ist schon in {} '{}', und ein Quader gehört zu einer Gruppe: nehmen Sie ihn zuerst aus '{}' heraus oder wählen Sie andere Quader</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="260"/>
        <source>constraint &apos;{}&apos;: a {} constraint takes one reference</source>
        <translation>Vorgabe '{}': eine {}-Vorgabe nimmt eine Referenz</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="283"/>
        <source>inner volume &apos;{}&apos;: choose the board it rests on (On)</source>
        <translation>Innenraum '{}': wählen Sie die Platte, auf der er steht (On)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="312"/>
        <source>add a master board (MasterBoards)</source>
        <translation>fügen Sie eine Rohplatte hinzu (MasterBoards)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="377"/>
        <source>{}: edit undone: {}
</source>
        <translation>{}: Änderung rückgängig gemacht: {}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="148"/>
        <source>Layout &apos;{}&apos;: {}{}</source>
        <translation>Layout '{}': {}{}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="165"/>
        <source>{}: {} parts on {} master board(s), usage {:.1%}, sheet utilisation {:.1%}
</source>
        <translation>{}: {} Teile auf {} Rohplatte(n), Nutzung {:.1%}, Plattenausnutzung {:.1%}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="196"/>
        <source>Layout &apos;{}&apos;: no boards to lay out (add FabGuide boards to Boards)</source>
        <translation>Layout '{}': keine Platten auszulegen (fügen Sie FabGuide-Platten zu Boards hinzu)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="199"/>
        <source>Layout &apos;{}&apos;: no master boards (add one to MasterBoards)</source>
        <translation>Layout '{}': keine Rohplatten (fügen Sie eine zu MasterBoards hinzu)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="203"/>
        <source>Layout &apos;{}&apos;: board &apos;{}&apos; has no shape; recompute it first</source>
        <translation>Layout '{}': Platte '{}' hat keine Form; erst neu berechnen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="231"/>
        <source>Layout &apos;{}&apos;: {} lie in one plane and touch, so they are cut as one piece; set their Quantity to 1</source>
        <translation>Layout '{}': {} liegen in einer Ebene und berühren sich, werden also als ein Stück geschnitten; setzen Sie ihre Quantity auf 1</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="285"/>
        <source>Layout &apos;{}&apos; has not been computed yet: recompute it first</source>
        <translation>Layout '{}' wurde noch nicht berechnet: erst neu berechnen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="293"/>
        <source>{} Mend that first: what was made now would show the last layout that could be made, not the boards as they are.</source>
        <translation>{} Beheben Sie das zuerst: was jetzt erstellt würde, zeigte das letzte Layout, das erstellt werden konnte, nicht die Platten, wie sie sind.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="25"/>
        <source>Design &apos;{}&apos;: parameter &apos;{}&apos; must read &apos;Sheet.alias min max&apos;</source>
        <translation>Entwurf '{}': Parameter '{}' muss 'Sheet.alias min max' lauten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="30"/>
        <source>Design &apos;{}&apos;: parameter &apos;{}&apos;: no spreadsheet &apos;{}&apos; with an alias &apos;{}&apos;</source>
        <translation>Entwurf '{}': Parameter '{}': keine Tabelle '{}' mit einem Alias '{}'</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="47"/>
        <source>Spreadsheet &apos;{}&apos;: &apos;{}&apos; holds no number ({})</source>
        <translation>Tabelle '{}': '{}' enthält keine Zahl ({})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="77"/>
        <source>Design &apos;{}&apos; has no Parameters</source>
        <translation>Entwurf '{}' hat keine Parameters</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/techdraw.py" line="58"/>
        <source>TechDraw&apos;s blank A4 template is not installed with this FreeCAD</source>
        <translation>Die leere A4-Vorlage von TechDraw ist mit diesem FreeCAD nicht installiert</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="124"/>
        <source>{}; kept {}
</source>
        <translation>{}; behalten: {}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/references.py" line="28"/>
        <source>{}; left out when opening the document
</source>
        <translation>{}; beim Öffnen des Dokuments ausgelassen
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="86"/>
        <source>see the report view</source>
        <translation>siehe Ausgabefenster</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="151"/>
        <source>&apos;{0}&apos; rides on &apos;{1}&apos; by the fixed joint &apos;{2}&apos;, and a part is moved by one joint: add this joint to &apos;{1}&apos; (they move together), or delete the fixed joint and hold &apos;{1}&apos; on &apos;{0}&apos; instead.</source>
        <translation>'{0}' sitzt über die feste Verbindung '{2}' auf '{1}', und ein Teil wird von einem Gelenk bewegt: fügen Sie dieses Gelenk '{1}' hinzu (sie bewegen sich zusammen), oder löschen Sie die feste Verbindung und halten Sie stattdessen '{1}' auf '{0}'.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="156"/>
        <source>&apos;{}&apos; is already moved by joint &apos;{}&apos; (a part is moved by one joint): pick the part to hold first, then the part it rides on.</source>
        <translation>'{}' wird schon vom Gelenk '{}' bewegt (ein Teil wird von einem Gelenk bewegt): wählen Sie zuerst das zu haltende Teil, dann das Teil, auf dem es sitzt.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="158"/>
        <source>&apos;{}&apos; is already moved by joint &apos;{}&apos; (a part is moved by one joint).</source>
        <translation>'{}' wird schon vom Gelenk '{}' bewegt (ein Teil wird von einem Gelenk bewegt).</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="97"/>
        <source>{:.1f} m</source>
        <translation>{:.1f} m</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="97"/>
        <source> ({:.1f} m shared, cut once)</source>
        <translation> ({:.1f} m gemeinsam, einmal geschnitten)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/core.py" line="12"/>
        <source>FabGuide&apos;s compiled core is not built for this FreeCAD (Python {}.{}){}: choose FabGuide &gt; Build the Core, or install the fabguide Debian package (README.md, Install).</source>
        <translation>FabGuides kompilierter Kern ist für dieses FreeCAD (Python {}.{}) nicht gebaut{}: wählen Sie FabGuide &gt; Kern bauen, oder installieren Sie das Debian-Paket fabguide (README.md, Install).</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/core.py" line="14"/>
        <source> (the one there does not load: {})</source>
        <translation> (der vorhandene lädt nicht: {})</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="13"/>
        <source>Configuration</source>
        <translation>Konfiguration</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="14"/>
        <source>joints</source>
        <translation>Gelenke</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="14"/>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="15"/>
        <source>a FabGuide part</source>
        <translation>ein FabGuide-Teil</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="15"/>
        <source>a FabGuide part (empty: the ground)</source>
        <translation>ein FabGuide-Teil (leer: der Boden)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="24"/>
        <source>Mechanism</source>
        <translation>Mechanismus</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="25"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="25"/>
        <source>a configuration</source>
        <translation>eine Konfiguration</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="217"/>
        <source>Mend the model as the note below says.</source>
        <translation>Beheben Sie das Modell, wie der Hinweis unten sagt.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="218"/>
        <source>Change or delete one of the relationships.</source>
        <translation>Ändern oder löschen Sie eine der Beziehungen.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="220"/>
        <source>Or unlock a box (the mechanism&apos;s Locks).</source>
        <translation>Oder geben Sie einen Quader frei (Locks des Mechanismus).</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="222"/>
        <source>Or move the parts that meet apart.</source>
        <translation>Oder rücken Sie die Teile, die aufeinandertreffen, auseinander.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="8"/>
        <source>Part</source>
        <translation>Teil</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="9"/>
        <source>Part::Box objects</source>
        <translation>Part::Box-Objekte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="21"/>
        <source>Printable</source>
        <translation>Druckteil</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/about.py" line="27"/>
        <source>About FabGuide</source>
        <translation>Über FabGuide</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/about.py" line="21"/>
        <source>Show the FabGuide version and the libraries it was built with</source>
        <translation>Die FabGuide-Version und die Bibliotheken zeigen, mit denen es gebaut wurde</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="38"/>
        <source>this FabGuide has no sources to build from ({}): install it again</source>
        <translation>dieses FabGuide hat keine Quellen zum Bauen ({}): installieren Sie es erneut</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="40"/>
        <source>cmake is not installed: in a terminal, run  sudo {}/tools/install-deps core</source>
        <translation>cmake ist nicht installiert: führen Sie in einem Terminal  sudo {}/tools/install-deps core  aus</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="45"/>
        <source>the build needs Debian packages that are not installed ({}): in a terminal, run  sudo {}/tools/install-deps core</source>
        <translation>der Bau braucht Debian-Pakete, die nicht installiert sind ({}): führen Sie in einem Terminal  sudo {}/tools/install-deps core  aus</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="54"/>
        <source>the build made no fabguide_core in {}</source>
        <translation>der Bau hat kein fabguide_core in {} erzeugt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="69"/>
        <source>Building the core for this FreeCAD (Python {}.{}) in {}</source>
        <translation>Der Kern wird für dieses FreeCAD (Python {}.{}) in {} gebaut</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="108"/>
        <source>The build stopped (exit status {}): the output above names the problem.</source>
        <translation>Der Bau brach ab (Exit-Status {}): die Ausgabe oben nennt das Problem.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="115"/>
        <source>The core could not be put into the workbench: {}</source>
        <translation>Der Kern konnte nicht in den Arbeitsbereich gelegt werden: {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="118"/>
        <source>Built {}. Restart FreeCAD to use FabGuide.</source>
        <translation>{} gebaut. Starten Sie FreeCAD neu, um FabGuide zu benutzen.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/busy.py" line="29"/>
        <source>{}: cancelled; it keeps its last result (recompute to try again)</source>
        <translation>{}: abgebrochen; das letzte Ergebnis bleibt (neu berechnen, um es erneut zu versuchen)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/busy.py" line="38"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/busy.py" line="52"/>
        <source>{}
stopping: keeping the best found so far</source>
        <translation>{}
hält an: das bisher Beste bleibt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/busy.py" line="61"/>
        <source>{}
{:.0f} s of at most {:.0f} s</source>
        <translation>{}
{:.0f} s von höchstens {:.0f} s</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="69"/>
        <source>Tool bit</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="69"/>
        <source>FreeCAD tool bits (*.fctb)</source>
        <translation>FreeCAD-Werkzeuge (*.fctb)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="78"/>
        <source>Folder for the G-code</source>
        <translation>Ordner für den G-Code</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="44"/>
        <source>{} (current)</source>
        <translation>{} (aktuell)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="44"/>
        <source>New configuration</source>
        <translation>Neue Konfiguration</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="85"/>
        <source>Configuration {}</source>
        <translation>Konfiguration {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="114"/>
        <source>Cannot show it: {}</source>
        <translation>Kann sie nicht zeigen: {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="114"/>
        <source>Moves: {}</source>
        <translation>Bewegt: {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="114"/>
        <source>Moves: nothing yet: tick the joints this configuration poses</source>
        <translation>Bewegt: noch nichts: haken Sie die Gelenke an, die diese Konfiguration stellt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="136"/>
        <source>The angle of {}: &quot;{}&quot; is not an angle from {:g} to {:g}; type it again.</source>
        <translation>Der Winkel von {}: &quot;{}&quot; ist kein Winkel von {:g} bis {:g}; geben Sie ihn erneut ein.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="138"/>
        <source>The offset of {}: &quot;{}&quot; is not a length from {:g} to {:g}; type it again.</source>
        <translation>Die Verschiebung von {}: &quot;{}&quot; ist keine Länge von {:g} bis {:g}; geben Sie sie erneut ein.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="143"/>
        <source>Select the flat-pack design to export.</source>
        <translation>Wählen Sie den Flachpack-Entwurf, der exportiert werden soll.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="73"/>
        <source>There is no flat-pack design in this document yet.</source>
        <translation>In diesem Dokument gibt es noch keinen Flachpack-Entwurf.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="334"/>
        <source>Select the flat-pack design.</source>
        <translation>Wählen Sie den Flachpack-Entwurf.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/editing.py" line="155"/>
        <source>closed</source>
        <translation>wurde geschlossen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/editing.py" line="155"/>
        <source>changed by undo or redo</source>
        <translation>wurde durch Rückgängig oder Wiederholen geändert</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="131"/>
        <source>Already in a part: {}</source>
        <translation>Schon in einem Teil: {}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="304"/>
        <source>Pick boxes of at least two parts; the last one picked is the covered part.</source>
        <translation>Wählen Sie Quader von mindestens zwei Teilen; der zuletzt gewählte ist das abgedeckte Teil.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="326"/>
        <source>Pick boxes of at least two parts; the last one picked is the enclosing part.</source>
        <translation>Wählen Sie Quader von mindestens zwei Teilen; der zuletzt gewählte ist das umschließende Teil.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="340"/>
        <source>Pick boxes of at least two parts; the last one picked is the supported part.</source>
        <translation>Wählen Sie Quader von mindestens zwei Teilen; der zuletzt gewählte ist das getragene Teil.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="358"/>
        <source>Pick exactly two faces of boxes.</source>
        <translation>Wählen Sie genau zwei Flächen von Quadern.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="360"/>
        <source>Pick faces of two different boxes: two faces of one box never lie in one plane.</source>
        <translation>Wählen Sie Flächen zweier verschiedener Quader: zwei Flächen eines Quaders liegen nie in einer Ebene.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="375"/>
        <source>Pick one or two edges of boxes, and nothing else (a face or a whole box says no length).</source>
        <translation>Wählen Sie eine oder zwei Kanten von Quadern und nichts anderes (eine Fläche oder ein ganzer Quader gibt keine Länge an).</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="416"/>
        <source>Select the mechanism to pose.</source>
        <translation>Wählen Sie den Mechanismus, der gestellt werden soll.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="82"/>
        <source>There is no mechanism in this document yet.</source>
        <translation>In diesem Dokument gibt es noch keinen Mechanismus.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="456"/>
        <source>Select the mechanism to export.</source>
        <translation>Wählen Sie den Mechanismus, der exportiert werden soll.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="465"/>
        <source>FabGuide wrote {}
</source>
        <translation>FabGuide hat {} geschrieben
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="478"/>
        <source>Select the mechanism to print.</source>
        <translation>Wählen Sie den Mechanismus, der gedruckt werden soll.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="505"/>
        <source>Select the printable to export.</source>
        <translation>Wählen Sie das Druckteil, das exportiert werden soll.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="505"/>
        <source>There is no printable in this document yet.</source>
        <translation>In diesem Dokument gibt es noch kein Druckteil.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="509"/>
        <source>Folder for the print files</source>
        <translation>Ordner für die Druckdateien</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="178"/>
        <source>FabGuide wrote:
  {}
</source>
        <translation>FabGuide hat geschrieben:
  {}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="72"/>
        <source>{}: &quot;{}&quot; is not a length from {:g} to {:g} mm; it stays {:g} mm.</source>
        <translation>{}: &quot;{}&quot; ist keine Länge von {:g} bis {:g} mm; es bleibt bei {:g} mm.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="96"/>
        <source>Band on the {} picked edge(s) (empty: none):</source>
        <translation>Umleimer auf der/den {} gewählten Kante(n) (leer: keiner):</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="131"/>
        <source>FabGuide: see the messages above for {}
</source>
        <translation>FabGuide: siehe die Meldungen oben zu {}
</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="165"/>
        <source>Select the layout to export.</source>
        <translation>Wählen Sie das Layout, das exportiert werden soll.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="23"/>
        <source>There is no layout in this document yet.</source>
        <translation>In diesem Dokument gibt es noch kein Layout.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="169"/>
        <source>Folder for the cut sheets</source>
        <translation>Ordner für die Zuschnittpläne</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="192"/>
        <source>Select the layout to draw.</source>
        <translation>Wählen Sie das Layout, das gezeichnet werden soll.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/relationship_panel.py" line="48"/>
        <source>&lt;br&gt;The solve changed:{}</source>
        <translation>&lt;br&gt;Das Lösen hat geändert:{}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="260"/>
        <source> (stopped)</source>
        <translation> (angehalten)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="22"/>
        <source>Board</source>
        <translation>Platte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="29"/>
        <source>Design</source>
        <translation>Entwurf</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="30"/>
        <source>master boards</source>
        <translation>Rohplatten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="95"/>
        <source>Constraint</source>
        <translation>Vorgabe</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="27"/>
        <source> (parts squared)</source>
        <translation> (Teilezahl zum Quadrat)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="27"/>
        <source>0 or a divisor of 90 (e.g. 15, 30, 45)</source>
        <translation>0 oder ein Teiler von 90 (z. B. 15, 30, 45)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="27"/>
        <source> (0: unlimited)</source>
        <translation> (0: unbegrenzt)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="27"/>
        <source>0 or more</source>
        <translation>0 oder mehr</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="289"/>
        <source>Layout &apos;{}&apos; is in error.</source>
        <translation>Layout '{}' ist fehlerhaft.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="10"/>
        <source>Master board</source>
        <translation>Rohplatte</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="11"/>
        <source> (as many as needed)</source>
        <translation> (so viele wie nötig)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="11"/>
        <source> (an offcut you have)</source>
        <translation> (ein vorhandener Rest)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="90"/>
        <source>master board &apos;{}&apos; is shared with {}</source>
        <translation>Rohplatte '{}' wird mit {} geteilt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="67"/>
        <source>greater than {:g}</source>
        <translation>größer als {:g}</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="72"/>
        <source>{:g}{} or more</source>
        <translation>{:g}{} oder mehr</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="100"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="135"/>
        <source>{} &apos;{}&apos;: {} must be a finite number</source>
        <translation>{} '{}': {} muss eine endliche Zahl sein</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="140"/>
        <source>{} &apos;{}&apos;: {} must be {}</source>
        <translation>{} '{}': {} muss {} sein</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/references.py" line="58"/>
        <source>{}: &apos;{}&apos; names no box (write &apos;Box label.{}&apos;)</source>
        <translation>{}: '{}' nennt keinen Quader (schreiben Sie 'Quaderbezeichnung.{}')</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="214"/>
        <source>Select the layout to machine.</source>
        <translation>Wählen Sie das Layout, das gefräst werden soll.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="339"/>
        <source>Design &apos;{}&apos;: {} could not be recomputed (see the report view). Mend that first: Suggest would start from their last shapes.</source>
        <translation>Entwurf '{}': {} konnte(n) nicht neu berechnet werden (siehe Ausgabefenster). Beheben Sie das zuerst: Vorschlagen ginge von ihren letzten Formen aus.</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="289"/>
        <source>Layout &apos;{}&apos;: {} could not be recomputed (see the report view).</source>
        <translation>Layout '{}': {} konnte(n) nicht neu berechnet werden (siehe Ausgabefenster).</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="34"/>
        <source>Design &apos;{}&apos;: parameter &apos;{}&apos; is {:g} now, outside its range</source>
        <translation>Entwurf '{}': Parameter '{}' ist jetzt {:g}, außerhalb seines Bereichs</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="79"/>
        <source>Make a flat-pack design of the selected Part boxes (boards, their thinnest side the thickness), cut from the master boards selected with them, or a new one of their thickness; boxes drawn the same size stay so (delete the &apos;drawn equal&apos; constraints to free them); its usage updates as you edit</source>
        <translation>Einen Flachpaket-Entwurf aus den gewählten Part-Quadern erstellen (Platten, ihre dünnste Seite ist die Dicke), zugeschnitten aus den mitgewählten Rohplatten oder einer neuen ihrer Dicke; gleich groß gezeichnete Quader bleiben gleich groß (löschen Sie die Bedingungen „drawn equal“, um sie freizugeben); die Ausnutzung wird beim Bearbeiten aktualisiert</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="175"/>
        <source>Solving &apos;{}&apos;</source>
        <translation>'{}' wird gelöst</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="119"/>
        <source>Making the bodies of &apos;{}&apos;</source>
        <translation>Die Körper von '{}' werden erzeugt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="429"/>
        <source>Laying out &apos;{}&apos;</source>
        <translation>'{}' wird angeordnet</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="143"/>
        <source>Laying out &apos;{}&apos; ({} boards)</source>
        <translation>'{}' wird angeordnet ({} Platten)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="314"/>
        <source>no boxes to lay out (drag the furniture&apos;s Part boxes into the design)</source>
        <translation>keine Quader zum Anordnen (die Part-Quader des Möbels in den Entwurf ziehen)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="64"/>
        <source>; with every board side as short as they allow, any layout of the boards needs {} sheet(s)</source>
        <translation>; mit jeder Plattenseite so kurz, wie sie es zulassen, braucht jede Anordnung der Platten {} Rohplatte(n)</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="67"/>
        <source>; with every board as small as they allow it was laid out on {} sheet(s), though by their sizes they would fit on {}: more time may save one</source>
        <translation>; mit jeder Platte so klein, wie sie es zulassen, wurde er auf {} Rohplatte(n) verlegt, obwohl sie nach ihren Maßen auf {} passen würden: mehr Zeit spart vielleicht eine</translation>
    </message>
</context>
<context>
    <name>FabGuidePreferences</name>
    <message>
        <location filename="../ui/Preferences.ui" line="5"/>
        <source>FabGuide</source>
        <translation>FabGuide</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="9"/>
        <source>Cutting (new layouts)</source>
        <translation>Zuschnitt (neue Layouts)</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="11"/>
        <source>Kerf</source>
        <translation>Schnittbreite</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="12"/>
        <source>Width of the cut: the laser beam or the router bit</source>
        <translation>Breite des Schnitts: Laserstrahl oder Fräser</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="46"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="13"/>
        <source>Spacing</source>
        <translation>Abstand</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="14"/>
        <source>Material left between parts besides the kerf</source>
        <translation>Material, das zusätzlich zur Schnittbreite zwischen den Teilen bleibt</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="15"/>
        <source>Edge trim</source>
        <translation>Randbeschnitt</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="16"/>
        <source>Margin kept along every master board edge</source>
        <translation>Rand, der an jeder Kante der Rohplatte frei bleibt</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="17"/>
        <source>Time limit</source>
        <translation>Zeitlimit</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="18"/>
        <source>Seconds a layout&apos;s search may take at most</source>
        <translation>Sekunden, die die Suche nach einem Layout höchstens dauern darf</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="18"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="24"/>
        <source>Master board (new master boards)</source>
        <translation>Rohplatte (neue Rohplatten)</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="26"/>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="27"/>
        <source>The sheet you buy, along the layout&apos;s x axis</source>
        <translation>Die Platte, die Sie kaufen, entlang der x-Achse des Layouts</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="28"/>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="29"/>
        <source>The sheet you buy, along the layout&apos;s y axis</source>
        <translation>Die Platte, die Sie kaufen, entlang der y-Achse des Layouts</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="30"/>
        <source>Thickness</source>
        <translation>Dicke</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="31"/>
        <source>Used when no board gives the thickness</source>
        <translation>Gilt, wenn keine Platte die Dicke vorgibt</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="37"/>
        <source>Printing in place (new printables)</source>
        <translation>Druck am Stück (neue Druckteile)</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="39"/>
        <source>Gap</source>
        <translation>Spalt</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="40"/>
        <source>Clearance between printed parts: 0.4 mm suits FDM, 0.2 mm resin</source>
        <translation>Spiel zwischen gedruckten Teilen: 0,4 mm für FDM, 0,2 mm für Harz</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="41"/>
        <source>Build volume width</source>
        <translation>Bauraumbreite</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="42"/>
        <source>Your printer&apos;s build volume along x</source>
        <translation>Der Bauraum Ihres Druckers entlang x</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="43"/>
        <source>Build volume depth</source>
        <translation>Bauraumtiefe</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="44"/>
        <source>Your printer&apos;s build volume along y</source>
        <translation>Der Bauraum Ihres Druckers entlang y</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="45"/>
        <source>Build volume height</source>
        <translation>Bauraumhöhe</translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="46"/>
        <source>Your printer&apos;s build volume along z</source>
        <translation>Der Bauraum Ihres Druckers entlang z</translation>
    </message>
</context>
<context>
    <name>LayoutPanel</name>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="6"/>
        <source>Layout</source>
        <translation>Zuschnitt</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="12"/>
        <source>Material usage</source>
        <translation>Materialnutzung</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="15"/>
        <source>Usage</source>
        <translation>Nutzung</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="15"/>
        <source>Part area / area of the rectangle the layout covers (the thesis&apos; measure)</source>
        <translation>Teilefläche / Fläche des Rechtecks, das das Layout bedeckt (das Maß der Dissertation)</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="26"/>
        <source>-</source>
        <translation>-</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="17"/>
        <source>Sheet utilisation</source>
        <translation>Plattenausnutzung</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="17"/>
        <source>Part area / area of the master boards used</source>
        <translation>Teilefläche / Fläche der benutzten Rohplatten</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="19"/>
        <source>Waste area</source>
        <translation>Verschnittfläche</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="21"/>
        <source>Master boards used</source>
        <translation>Benutzte Rohplatten</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="23"/>
        <source>Saw cuts</source>
        <translation>Sägeschnitte</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="23"/>
        <source>Guillotine cuts: how many, and their total length (the cut sequence is on the cut sheets)</source>
        <translation>Guillotineschnitte: wie viele und ihre Gesamtlänge (die Schnittfolge steht auf den Zuschnittplänen)</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="33"/>
        <source>Cutting</source>
        <translation>Zuschnitt</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="36"/>
        <source>Kerf</source>
        <translation>Schnittbreite</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="38"/>
        <source>Spacing</source>
        <translation>Abstand</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="40"/>
        <source>Edge trim</source>
        <translation>Randbeschnitt</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="42"/>
        <source>Cuts</source>
        <translation>Schnitte</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="42"/>
        <source>Free: any outline (CNC router, laser). Guillotine: straight cuts from edge to edge only (panel, track or table saw)</source>
        <translation>Frei: jeder Umriss (CNC-Fräse, Laser). Guillotine: nur gerade Schnitte von Kante zu Kante (Plattensäge, Tauchsäge oder Tischkreissäge)</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="44"/>
        <source>Stages</source>
        <translation>Stufen</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="44"/>
        <source>Guillotine cuts: at most this many changes of direction; 0 = unlimited</source>
        <translation>Guillotineschnitte: höchstens so viele Richtungswechsel; 0 = unbegrenzt</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="45"/>
        <source>Unlimited</source>
        <translation>Unbegrenzt</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="46"/>
        <source>First cut</source>
        <translation>Erster Schnitt</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="46"/>
        <source>Guillotine cuts: the first cuts along the sheet&apos;s length, across it, or whichever wastes less</source>
        <translation>Guillotineschnitte: die ersten Schnitte längs der Platte, quer dazu oder wie es weniger Verschnitt gibt</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="25"/>
        <source>Cut length</source>
        <translation>Schnittlänge</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="25"/>
        <source>Every outline and hole; with shared lines cut once, a line two boards share counted once</source>
        <translation>Alle Umrisse und Löcher; werden gemeinsame Linien einmal geschnitten, zählt eine Linie, die zwei Platten teilen, einmal</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="48"/>
        <source>Cut shared lines once</source>
        <translation>Gemeinsame Linien einmal schneiden</translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="48"/>
        <source>Common-line cutting: where two boards lie a kerf apart (spacing 0), the line between them is cut once, by the board cut first. The machine&apos;s paths only (not as designed)</source>
        <translation>Gemeinsamer Schnitt: wo zwei Platten eine Schnittbreite auseinander liegen (Abstand 0), wird die Linie zwischen ihnen einmal geschnitten, mit der zuerst geschnittenen Platte. Nur für die Bahnen der Maschine (nicht wie konstruiert)</translation>
    </message>
</context>
<context>
    <name>RelationshipPanel</name>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="6"/>
        <source>Relationship</source>
        <translation>Beziehung</translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="17"/>
        <source>Corresponding faces</source>
        <translation>Zugehörige Flächen</translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="22"/>
        <source>Blue → red in the 3-D view: first → second. Pick two faces there and press Add; double-click a pair to retype it.</source>
        <translation>Blau → Rot in der 3D-Ansicht: erste → zweite. Wählen Sie dort zwei Flächen und drücken Sie Hinzufügen; ein Doppelklick auf ein Paar gibt ihm einen anderen Typ.</translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="28"/>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="28"/>
        <source>Add the two faces picked in the 3-D view as a pair</source>
        <translation>Die zwei in der 3D-Ansicht gewählten Flächen als Paar hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="29"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="29"/>
        <source>Remove the selected pairs</source>
        <translation>Die ausgewählten Paare entfernen</translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="30"/>
        <source>Re-infer</source>
        <translation>Neu ableiten</translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="30"/>
        <source>Forget the pairs and infer them again on a solve</source>
        <translation>Die Paare vergessen und beim Lösen neu ableiten</translation>
    </message>
</context>
<context>
    <name>SuggestPanel</name>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="22"/>
        <source>Suggest</source>
        <translation>Vorschlagen</translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="12"/>
        <source>Time limit</source>
        <translation>Zeitlimit</translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="13"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="14"/>
        <source>Threads</source>
        <translation>Threads</translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="16"/>
        <source>Seed</source>
        <translation>Startwert</translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="23"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="31"/>
        <source>Path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="36"/>
        <source>Keep these parts&apos; sizes from the suggestion:</source>
        <translation>Diese Teilegrößen aus dem Vorschlag übernehmen:</translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="38"/>
        <source>Apply, keep, suggest again</source>
        <translation>Übernehmen, behalten, neu vorschlagen</translation>
    </message>
</context>
<context>
    <name>Workbench</name>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="33"/>
        <source>Parts</source>
        <translation>Teile</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="35"/>
        <source>Joints</source>
        <translation>Gelenke</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="37"/>
        <source>Relationships</source>
        <translation>Beziehungen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="39"/>
        <source>Print in place</source>
        <translation>In einem Stück drucken</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="41"/>
        <source>Works-like file</source>
        <translation>Funktionsmodell-Datei</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="43"/>
        <source>Boards</source>
        <translation>Platten</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="45"/>
        <source>Cut sheets</source>
        <translation>Zuschnittpläne</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="47"/>
        <source>Design constraints</source>
        <translation>Entwurfsbedingungen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="49"/>
        <source>Volumes</source>
        <translation>Volumen</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="51"/>
        <source>Flat-pack file</source>
        <translation>Flachpaket-Datei</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="56"/>
        <source>Function</source>
        <translation>Funktion</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="57"/>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="58"/>
        <source>Zero waste</source>
        <translation>Kein Verschnitt</translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="59"/>
        <source>Zero-waste design</source>
        <translation>Entwurf ohne Verschnitt</translation>
    </message>
</context>
</TS>
