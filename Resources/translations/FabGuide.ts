<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1">
<context>
    <name>App::Property</name>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="18"/>
        <source>The joints it moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="20"/>
        <source>Per joint: for a double pivot, the point its part turns about to get here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="21"/>
        <source>The part the joint moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="22"/>
        <source>The part it hangs on, which carries it along when it moves; empty: the ground</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="26"/>
        <source>The edge of one of the part&apos;s boxes it turns about</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="29"/>
        <source>The direction it slides along</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="32"/>
        <source>The face of the part&apos;s box with the pivot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="34"/>
        <source>The pivot on the part (placed by the solve)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="36"/>
        <source>The face of the base&apos;s box, in the same plane, with the other pivot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="39"/>
        <source>The pivot on the base (placed by the solve)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="31"/>
        <source>Smallest size of a box along any axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="33"/>
        <source>Least wall around a cavity on its sides that are not openings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="37"/>
        <source>Box coordinates you changed since the last solve keep their new value while the rest adapts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="40"/>
        <source>The configuration the Configurations panel last showed; new relationships hold in it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="43"/>
        <source>Solved, or the relationships in conflict</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="45"/>
        <source>Largest constraint violation after the solve, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="48"/>
        <source>Parts a conflict blames besides its relationships&apos; (overlapping parts, thin walls)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="51"/>
        <source>What the last solve changed: box, size old → new, how far it moved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="54"/>
        <source>Box coordinates after the last solve (JSON)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="56"/>
        <source>Box sizes as you drew them, before solves (JSON)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="13"/>
        <source>The axis-aligned boxes (Part::Box) the part is made of</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="15"/>
        <source>Boxes cut out of it: openings and compartments that can be covered or fitted into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="26"/>
        <source>The mechanism to print in place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="28"/>
        <source>Printer profile: the gap it needs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="30"/>
        <source>Clearance between parts (set by the printer profile)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="33"/>
        <source>Print at this scale (0.2 for 1:5); the gap stays as it is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="35"/>
        <source>Print at the largest scale (at most 1) that fits the build volume; sets Scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="38"/>
        <source>The printer&apos;s build volume in mm: width (x), depth (y), height (z); the print may turn a quarter about z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="42"/>
        <source>Width x depth x height of the print</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="44"/>
        <source>Fitted turned a quarter about z: exported so, shown as modelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="47"/>
        <source>Show the volumes swept into cavities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="49"/>
        <source>Measure the clearance at 32 poses along every configuration&apos;s motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="52"/>
        <source>Least distance between two bodies</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="54"/>
        <source>Where the least distance is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="56"/>
        <source>Joints made without geometry, and why</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="14"/>
        <source>The configuration it must hold in; empty: as modelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="16"/>
        <source>Satisfied, or what it conflicts with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="25"/>
        <source>Parts whose faces cover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="27"/>
        <source>Parts whose faces are covered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="29"/>
        <source>Just cover: the covering faces no larger than the covered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="46"/>
        <source>Parts that must fit inside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="48"/>
        <source>The part they fit inside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="50"/>
        <source>A cavity of the enclosing part to fit in; empty: its box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="52"/>
        <source>Partial fit: the boxes of the inner parts that must fit (a drawer&apos;s tray, not its front); empty: all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="59"/>
        <source>Each inner part just fits on its own along the ticked axes (stacked trays without play), not only the inner parts taken together</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="80"/>
        <source>Parts that support (legs, frames)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="82"/>
        <source>Parts resting on them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="100"/>
        <source>Two box faces that lie in one plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="120"/>
        <source>Left = or &lt;= right + offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="125"/>
        <source>Added to the right side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="27"/>
        <source>Sketch, planar face or thin solid the board is made of</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="29"/>
        <source>Thickness of a board made from a sketch or face (detected for a solid)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="32"/>
        <source>How many to cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="33"/>
        <source>Turns allowed on the master board: any, keeping its length along the grain, or none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="43"/>
        <source>Longest side of the outline&apos;s box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="45"/>
        <source>Other side of the outline&apos;s box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="36"/>
        <source>Master boards to cut the boards from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="38"/>
        <source>Grid cell size tau (thesis 5.4.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="40"/>
        <source>Width of the cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="41"/>
        <source>Extra material between parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="43"/>
        <source>Margin cut off every master board edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="48"/>
        <source>Boards that touch stay touching (edge snapping)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="50"/>
        <source>How many times its length now Suggest may make a board&apos;s side (1.5: half as long again), so a batten stays a batten; your own edits are not held</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="54"/>
        <source>A box you edit keeps its new size and place while the rest adapts to the constraints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="57"/>
        <source>Spreadsheet aliases that drive the boxes by expressions, as &apos;Sheet.alias min max&apos; (thesis 5.4.2.2); when given, Suggest changes these instead of the boxes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="61"/>
        <source>Part area / layout bounding rectangle (thesis 5.2.3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="64"/>
        <source>Laid out, or what is wrong</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="66"/>
        <source>What the last recompute or accepted suggestion that moved boards did: size old → new, how far</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="70"/>
        <source>Boards after the last valid recompute (JSON)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="99"/>
        <source>What must hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="106"/>
        <source>Boxes for ground, coplanar and snap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="108"/>
        <source>Fixed value or sum offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="110"/>
        <source>Range: smallest value (beyond ±10⁸ m: none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="113"/>
        <source>Range: largest value (beyond ±10⁸ m: none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="118"/>
        <source>Satisfied, or what breaks it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="136"/>
        <source>Inner: kept free; Outer: the design stays inside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="139"/>
        <source>Inner volume: the board it rests on and moves with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="141"/>
        <source>Size along x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="142"/>
        <source>Size along y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="143"/>
        <source>Size along z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="144"/>
        <source>Satisfied, or the boards that break it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="211"/>
        <source>The model axis the wood&apos;s grain runs along, one in the board&apos;s face: the board is laid with it along the grain of master boards that have one. Free: no grain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="39"/>
        <source>Boards to lay out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="40"/>
        <source>Master boards to cut them from, opened in this order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="42"/>
        <source>Width of the cut (laser beam, router bit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="45"/>
        <source>Material left between parts besides the kerf</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="48"/>
        <source>Margin kept along every master board edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="51"/>
        <source>Router bit diameter: the cut sheets relieve inside corners (slots, notches) so the bit cuts them square; 0 for none (a laser)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="54"/>
        <source>Holding tabs left in the outer cut of small parts so they stay in the sheet; 0 for none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="57"/>
        <source>Parts whose longer side is shorter get holding tabs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="64"/>
        <source>Export the parts&apos; outlines as designed (no kerf offset, no dogbones, closed, holding tabs on a layer of their own) for CAM software that offsets by its tool itself; off: tool paths as a laser or the machine cuts them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="69"/>
        <source>Labels as text in a font; off: as single strokes to engrave, which laser software, CAM and FreeCAD&apos;s DXF import take as they are</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="72"/>
        <source>Width of the label printer&apos;s labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="74"/>
        <source>Height of the label printer&apos;s labels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="76"/>
        <source>Connectors where boards meet: finger joints or cross slots; dowels for boards of 18 mm or more under Auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="79"/>
        <source>Free: any outline (a CNC router or laser follows it); Guillotine: straight cuts from edge to edge only (a panel, track or table saw), with the cut sequence on the cut sheets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="83"/>
        <source>Guillotine cuts: at most this many changes of direction (2, 3, ...); 0 = unlimited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="86"/>
        <source>Guillotine cuts: the first cuts along the sheet&apos;s length (x), across it, or whichever wastes less</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="90"/>
        <source>The connectors made</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="92"/>
        <source>Guillotine cuts: the saw cuts to make</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="94"/>
        <source>Guillotine cuts: their total length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="103"/>
        <source>Cell size of the layout grid (thesis 5.4.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="105"/>
        <source>Free rotation: boards without grain may turn by every multiple of this many degrees (a divisor of 90, e.g. 15); 0 = quarter turns only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="108"/>
        <source>Ordering swaps tried; -1 = parts squared (thesis 5.4.3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="110"/>
        <source>Seed of the ordering search</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="112"/>
        <source>Seconds the search may take at most; in FreeCAD a dialog shows it and Stop keeps the best layout so far</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="116"/>
        <source>Part area / bounding rectangle of the layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="118"/>
        <source>Part area / area of the master boards used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="121"/>
        <source>Area of the master boards used minus part area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="123"/>
        <source>Master boards used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="125"/>
        <source>The problem laid out (*.pack.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="127"/>
        <source>The layout (layout JSON)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="17"/>
        <source>Size along the layout&apos;s x axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="19"/>
        <source>Size along the layout&apos;s y axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="21"/>
        <source>Material thickness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="23"/>
        <source>Boards in stock; 0 = as many as needed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="25"/>
        <source>Material name for the cut list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="27"/>
        <source>Direction of the wood grain; boards set to Follow grain keep their length along it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="30"/>
        <source>What one board costs (any unit; 1 = a sheet); 0 for an offcut you have, which is used before new sheets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="111"/>
        <source>Why the last recompute failed; empty when it did not</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="55"/>
        <source>Just fits in width (along X)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="55"/>
        <source>Just fits in depth (along Y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="55"/>
        <source>Just fits in height (along Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="36"/>
        <source>Band glued on its first long edge (e.g. &apos;oak 1 mm&apos;); empty: none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="36"/>
        <source>Band glued on its second long edge (e.g. &apos;oak 1 mm&apos;); empty: none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="36"/>
        <source>Band glued on its first short edge (e.g. &apos;oak 1 mm&apos;); empty: none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="36"/>
        <source>Band glued on its second short edge (e.g. &apos;oak 1 mm&apos;); empty: none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="60"/>
        <source>Common-line cutting: a line two boards a kerf apart share is cut once, by the board cut first (Spacing 0 lays boards so); the machine&apos;s paths only, not AsDesigned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="96"/>
        <source>Length of all cuts: the saw&apos;s for guillotine cuts, else every outline and hole, a line two boards share counted once with CommonLine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="100"/>
        <source>CommonLine: the length of the lines two boards share, cut once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="49"/>
        <source>How far the joint turns its part (right-handed about its edge&apos;s +x/+y/+z direction)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="52"/>
        <source>How far the joint slides its part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="35"/>
        <source>Coordinates that keep their value: a box and its side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="158"/>
        <source>The body this shape is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="31"/>
        <source>Corresponding faces, two by two: &apos;covering -&gt; covered&apos; (thesis 4.3.1); empty: inferred on the next solve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="31"/>
        <source>How far apart faces may be to correspond when inferring the pairs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="84"/>
        <source>Corresponding faces, two by two: &apos;supporting top -&gt; supported bottom&apos; (thesis 4.3.3); empty: inferred on the next solve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="84"/>
        <source>How far above a top face a bottom face may be when inferring the pairs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="115"/>
        <source>Quantities summed: a box and its side or size (width/depth/height), with a factor in front if not 1 (the formats write &apos;Door.width&apos;, &apos;2*Shelf.height&apos;, &apos;-Lid.left&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="123"/>
        <source>Quantities summed (may be empty)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="191"/>
        <source>The layout this was made from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="101"/>
        <source>Boxes and what of them (size.x, centre.z, min.y, max.x): equal, symmetric (two), sum (left side), fixed and range (one)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="105"/>
        <source>Right side of a sum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="116"/>
        <source>Symmetric about this reference (empty: midway now)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="34"/>
        <source>The designs and layouts cut from this master board: a change reaches them all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/techdraw.py" line="62"/>
        <source>The layout this page draws</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="38"/>
        <source>The FabGuide version that wrote this</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="45"/>
        <source>Shortest side a board may shrink to; 0: twice each board&apos;s own thickness, as a file without min_length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="72"/>
        <source>The last layout, its problem and the design it was made from (JSON)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CamJobPanel</name>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="6"/>
        <source>Make CAM Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="12"/>
        <source>One CAM job per master board: the sheet as stock, the parts as solids, profiles from their outlines as designed (the tool&apos;s radius is CAM&apos;s), holding tags, dogbones, dowel drilling and engraved labels as the layout asks.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="17"/>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="19"/>
        <source>Tool bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="19"/>
        <source>The end mill that profiles the parts (a FreeCAD tool bit file, *.fctb)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="23"/>
        <source>Other…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="26"/>
        <source>Post-processor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="26"/>
        <source>The G-code dialect of your machine&apos;s controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="28"/>
        <source>Per material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="28"/>
        <source>The feed across the sheet and the spindle speed for each material of the layout&apos;s master boards (remembered for the next job)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="40"/>
        <source>Cut through by</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="40"/>
        <source>How far the profiles cut below the sheet, into the spoilboard, so that the parts come free (0: to the sheet&apos;s underside)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="41"/>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="47"/>
        <source>Write G-code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="52"/>
        <source>Folder…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="34"/>
        <source>Feed
mm/min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/CamJobPanel.ui" line="36"/>
        <source>Spindle
rpm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ConfigurationsPanel</name>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="6"/>
        <source>Configurations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="11"/>
        <source>Configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="13"/>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="19"/>
        <source>Joints it poses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="20"/>
        <source>Tick the joints this configuration poses; an angle&apos;s sign is the way the part swings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="26"/>
        <source>Move the mechanism from its base pose to the configuration, the way the print moves: turns first, then slides</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="34"/>
        <source>Base</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="34"/>
        <source>The left end of the slider: the base pose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="35"/>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="36"/>
        <source>Posed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/ConfigurationsPanel.ui" line="36"/>
        <source>The right end of the slider: the configuration</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FabGuide</name>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="22"/>
        <source>&apos;{}&apos; is rotated: FabGuide parts are axis-aligned boxes (reset its Placement rotation; joints turn parts in configurations)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="28"/>
        <source>&apos;{}&apos;: its Length, Width, Height and Placement must be finite numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="76"/>
        <source>&apos;{}.{}&apos; is not a face of the box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="95"/>
        <source>&apos;{}.{}&apos; is not an edge of the box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/cuboids.py" line="104"/>
        <source>&apos;{}&apos; has no edge between its {} and {} faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="98"/>
        <source>Configuration &apos;{}&apos;: &apos;{}&apos; is not a joint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="116"/>
        <source>Joint &apos;{}&apos;: choose the Part it moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="122"/>
        <source>Joint &apos;{}&apos;: choose the Edge it turns about</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="125"/>
        <source>Joint &apos;{}&apos;: its edge is on &apos;{}&apos;, which is not a box of part &apos;{}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="130"/>
        <source>Joint &apos;{}&apos;: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="134"/>
        <source>Fixed joint &apos;{}&apos;: choose the Base part it holds &apos;{}&apos; to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="138"/>
        <source>Double pivot &apos;{}&apos;: choose the Base part it links to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="143"/>
        <source>Double pivot &apos;{}&apos;: choose a face of a box of &apos;{}&apos; for its {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="178"/>
        <source>Mechanism &apos;{}&apos;: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="201"/>
        <source>{}: these cannot hold together: {}. {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="39"/>
        <source>Part &apos;{}&apos; has no boxes: add a Part::Box to its Cuboids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="44"/>
        <source>Part &apos;{}&apos;: &apos;{}&apos; is not a Part::Box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="71"/>
        <source>Printable &apos;{}&apos;: the mechanism has new parts ({}); run Make Printable again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="92"/>
        <source>Printable &apos;{}&apos;: invalid solids: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="95"/>
        <source>Printable &apos;{}&apos;: bodies that print in pieces ({}): a cut went through them, a joint turning the wrong way round or a part in the way</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="100"/>
        <source>{}: parts come within {:.3f} mm of each other ({}), less than the {} mm gap
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="116"/>
        <source>Printable &apos;{}&apos;: choose the Mechanism to print</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="122"/>
        <source>Printable &apos;{}&apos;: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="132"/>
        <source>Printable &apos;{}&apos;: BuildVolume must be greater than 0 in x, y and z (is {:g} x {:g} x {:g})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="177"/>
        <source>Printable &apos;{}&apos;: {}; mend that first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="181"/>
        <source>Printable &apos;{}&apos;: not made from the mechanism as it stands ({} changed); recompute first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="187"/>
        <source>Printable &apos;{}&apos;: {} not made yet; recompute it first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="65"/>
        <source>Fit inside &apos;{}&apos;: choose the Enclosing part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="106"/>
        <source>Flush &apos;{}&apos;: choose exactly two faces, got {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="146"/>
        <source>Geometric &apos;{}&apos;: &apos;{}&apos; must read &apos;Box.side&apos;, &apos;Box.width&apos; or &apos;factor*Box.width&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="168"/>
        <source>{} &apos;{}&apos;: its Pairs lost a face (a box was deleted?); re-infer them (clear Pairs) or correct them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/relationships.py" line="216"/>
        <source>{} &apos;{}&apos;: pair &apos;{}&apos; must read &apos;Box.side -&gt; Box.side&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="154"/>
        <source>Build FabGuide&apos;s core</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="125"/>
        <source>Cancelled: nothing was installed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="133"/>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="152"/>
        <source>FabGuide: the core cannot be built: {}.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="154"/>
        <source>The core cannot be built: {}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/command_base.py" line="31"/>
        <source>FabGuide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="94"/>
        <source>&lt;b&gt;No CAM job made:&lt;/b&gt; {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/command_base.py" line="30"/>
        <source>FabGuide: {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="99"/>
        <source>FabGuide: {} CAM job(s) for &apos;{}&apos;{}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/command_base.py" line="144"/>
        <source>{}: cannot use &apos;{}&apos;: {}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/command_base.py" line="156"/>
        <source>{} did not finish: {} ({}). Please report this, with what you did, at the FabGuide issue tracker.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="33"/>
        <source>Make a mechanism, a part or a cavity from boxes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="35"/>
        <source>Add a joint: hinge, slide, sliding hinge, double pivot or fixed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="37"/>
        <source>Add a relationship: cover, fit inside, support, flush or geometric</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="39"/>
        <source>Make the mechanism printable in place, or export the print</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="41"/>
        <source>Import or export a *.workslike.json model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="43"/>
        <source>Make boards from thin solids, or from a sketch or face; band their edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="45"/>
        <source>Export cut sheets, make TechDraw pages or CAM jobs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="47"/>
        <source>Add a design constraint on the picked boards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="49"/>
        <source>Add an inner (kept free) or the outer volume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="51"/>
        <source>Import or export a *.flatpack.json design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="57"/>
        <source>Angle: its sign is the way the part swings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="58"/>
        <source>Offset along the slide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="122"/>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="125"/>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="51"/>
        <source>Pick boxes of one flat-pack design (use Flat-pack Design from Boxes first).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="66"/>
        <source>{} does not hold for the design as it is: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="78"/>
        <source>Flat-pack Design from Boxes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="88"/>
        <source>Select the Part boxes your furniture is made of first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="105"/>
        <source>Import Flat-pack Design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="106"/>
        <source>Open a *.flatpack.json design: boxes, master boards, constraints and volumes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="118"/>
        <source>Cannot import {}: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="137"/>
        <source>Export Flat-pack Design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="138"/>
        <source>Write the selected design as *.flatpack.json (for `fabguide optimise` and bug reports)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="168"/>
        <source>Pick an edge of a box for {}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="168"/>
        <source>Pick edges of boxes for {}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="178"/>
        <source>Equal Lengths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="179"/>
        <source>The picked edges of boards keep equal lengths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="183"/>
        <source>Sum of Lengths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="184"/>
        <source>The lengths of the picked edges add up to the length of the last one picked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="192"/>
        <source>Fixed Length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="193"/>
        <source>Each picked edge keeps its present length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="202"/>
        <source>Length Range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="203"/>
        <source>Each picked edge may change by at most 25 % (edit Min and Max of the constraint)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="213"/>
        <source>Equal Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="214"/>
        <source>The picked faces of boards stay level with each other (same coordinate along their normal)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="222"/>
        <source>Pick two or more parallel faces of boards for Equal Position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="238"/>
        <source>Pick {} for {}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="246"/>
        <source>Ground Touching</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="247"/>
        <source>The picked boards keep standing on the ground (their lowest face at the lowest board&apos;s level)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="252"/>
        <source>Coplanar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="253"/>
        <source>The picked parallel boards stay in one plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="258"/>
        <source>Snap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="259"/>
        <source>Two touching boards stay touching, flush where they are flush (designs snap all contacts by default)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="265"/>
        <source>Symmetric</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="266"/>
        <source>Two boards stay mirror images about the plane midway between them (along the axis that separates them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="286"/>
        <source>Inner Volume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="287"/>
        <source>Space that must stay free, resting on the picked board (a shelf for binders); edit its size and place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="294"/>
        <source>Pick the one board the free space rests on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="305"/>
        <source>Outer Volume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="306"/>
        <source>An envelope the selected design must stay inside (its box now, 10 % larger); edit its size and place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="316"/>
        <source>Design &apos;{}&apos; has no boxes to put an envelope round.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="327"/>
        <source>Suggest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="328"/>
        <source>Search for design variations that keep your constraints and waste less material (or, for a design with Parameters, spreadsheet values within their ranges); preview and accept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/editing.py" line="44"/>
        <source>Another task panel is open: finish it with OK or Cancel first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/editing.py" line="155"/>
        <source>FabGuide: the task panel closed: its document {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="87"/>
        <source>Mechanism from Boxes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="88"/>
        <source>Make a mechanism; each selected box (Part::Box) becomes one of its parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="94"/>
        <source>Every picked box is already in a part: pick boxes that are not.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="102"/>
        <source>Part from Boxes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="103"/>
        <source>Make one part of the selected boxes: they move together</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="109"/>
        <source>Select the boxes (Part::Box) the part is made of.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="119"/>
        <source>Cavity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="120"/>
        <source>Select a box of a part, then boxes to cut out of it: openings and compartments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="127"/>
        <source>Select a box of the part first, then the boxes that are cavities in it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="172"/>
        <source>Pick the one edge of a box the {} turns about.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="175"/>
        <source>Pick a face of a box: the part slides along its normal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="191"/>
        <source>Add Hinge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="192"/>
        <source>Pick an edge of a box: its part turns about it (and a box of another part it hangs on, if any)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="198"/>
        <source>Add Slide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="199"/>
        <source>Pick a face of a box: its part slides along the face&apos;s normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="204"/>
        <source>Add Sliding Hinge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="205"/>
        <source>Pick an edge and a face of a box: its part turns about the edge, which slides along the face&apos;s normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="211"/>
        <source>Add Double Pivot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="212"/>
        <source>Pick a point on a face of the moving part&apos;s box, then one on the face of the part it links to, in the same plane: a rigid link joins them (the solve places both pivots)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="221"/>
        <source>Pick a point on a face of the moving part&apos;s box, then one on the face of the part it links to.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="234"/>
        <source>Add Fixed Joint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="235"/>
        <source>Pick a box of the part to hold, then a box of the part it rides on: it moves with that part and prints as one body with it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="242"/>
        <source>Pick a box of the part to hold, then a box of the part it rides on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="245"/>
        <source>Both boxes are in one part: pick a box of the part to hold, then one of another part.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="248"/>
        <source>&apos;{}&apos; already rides on &apos;{}&apos;: pick the part to hold first, then the part it rides on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="303"/>
        <source>Add Cover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="306"/>
        <source>These parts cover that one (picked last): faces in one plane, packed, covering its faces or openings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="328"/>
        <source>Add Fit Inside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="329"/>
        <source>These parts fit inside that one (picked last; pick one of its cavities to fit in it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="342"/>
        <source>Add Support</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="343"/>
        <source>These parts support that one (picked last): it rests on their tops; they stand on one ground</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="351"/>
        <source>Add Flush</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="352"/>
        <source>Pick two faces of boxes: they lie in one plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="368"/>
        <source>Add Geometric</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="369"/>
        <source>Pick two edges of boxes: their lengths stay equal (one edge: its length stays as it is now)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="390"/>
        <source>Solve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="391"/>
        <source>Solve the selected (or every) mechanism: the least change that makes its relationships hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="398"/>
        <source>There is no mechanism yet: use Mechanism from Boxes first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="408"/>
        <source>Configurations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="409"/>
        <source>Pose the joints: name configurations and move the mechanism between them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="422"/>
        <source>Import Works-like Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="423"/>
        <source>Build a mechanism from a *.workslike.json file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="447"/>
        <source>Export Works-like Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="448"/>
        <source>Write the selected mechanism as a *.workslike.json file (the CLI&apos;s fabguide solve reads it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="469"/>
        <source>Make Printable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="470"/>
        <source>Print-in-place bodies of the selected (or only) mechanism: gaps, cavities, hinge pins and yokes, pivot links; checked along every motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="489"/>
        <source>{}: least clearance {:.3f} mm ({})
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="494"/>
        <source>Export Printable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="495"/>
        <source>Write the selected printable as STL, 3MF and STEP: the assembly and one file per body</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="53"/>
        <source>&lt;i&gt;The layout is made again when you pause.&lt;/i&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="86"/>
        <source>&lt;b&gt;The layout could not be made:&lt;/b&gt; {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="27"/>
        <source>New Master Board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="28"/>
        <source>Add a master board (sheet size, thickness, stock, material) to cut boards from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="41"/>
        <source>Make Board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="42"/>
        <source>Make a board from each selected sketch or planar face, as thick as the master boards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="50"/>
        <source>Select sketches or planar faces first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="61"/>
        <source>Boards from Solids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="62"/>
        <source>Turn each selected thin solid into a board, detecting its thickness and outline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="70"/>
        <source>Select the solids of your furniture model (flat boxes, pads, extrusions) first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="96"/>
        <source>Band Edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="82"/>
        <source>Glue edge banding on the picked edge faces of boards (asks for the band&apos;s name; empty removes it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="94"/>
        <source>Pick the edge faces of boards (their narrow sides, not the large faces) first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="107"/>
        <source>FabGuide: {} on {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="122"/>
        <source>Nothing made: {}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="26"/>
        <source>Layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="137"/>
        <source>Lay the selected (or all) boards out on the master boards and show the material usage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="144"/>
        <source>There are no boards yet: use Boards from Solids or Make Board first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="157"/>
        <source>Export Cut Sheets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="158"/>
        <source>Write SVG and DXF cut sheets per master board, a CSV cut list, the shop&apos;s PDF report and part labels for the selected layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="182"/>
        <source>TechDraw Pages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="183"/>
        <source>Make TechDraw pages of the selected layout&apos;s shop report: a page per master board (parts numbered and sized, grain, edge banding, saw cuts), then the cut list and the totals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="204"/>
        <source>Make CAM Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="205"/>
        <source>Make a FreeCAD CAM job per master board of the selected layout (profiles, tags, dogbones, drilling, engraved labels) with your tool and post-processor, and write its G-code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/relationship_panel.py" line="48"/>
        <source>&lt;b style=&apos;color:{}&apos;&gt;{}&lt;/b&gt;{}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/relationship_panel.py" line="67"/>
        <source>&lt;b&gt;Pick two faces of boxes in the 3-D view&lt;/b&gt; (the first, then the second of the pair) and press Add; {} picked.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/relationship_panel.py" line="143"/>
        <source>&lt;b style=&apos;color:#b22222&apos;&gt;{}&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="82"/>
        <source>Suggest cannot change {}: their sizes or places are set by expressions. Give Design &apos;{}&apos; the spreadsheet aliases that drive them as Parameters (&apos;Sheet.alias min max&apos;), and Suggest changes those.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="371"/>
        <source>Design &apos;{}&apos;: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="349"/>
        <source>Usage now: {:.3f}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="200"/>
        <source>Searching for designs that waste less...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="235"/>
        <source>Searching... best usage so far {:.3f}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="243"/>
        <source>&lt;b&gt;No suggestions:&lt;/b&gt; {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="263"/>
        <source>No variation of this design wastes less within its constraints{}{}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="267"/>
        <source>{} suggestion(s) in {:.1f} s{}. Pick one; slide along its path; OK applies it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="285"/>
        <source>Suggestion {}: {} sheet(s) (now {}), waste {:.3f} m² (now {:.3f}), largest offcut {:.0f} x {:.0f} mm, usage {:.3f} (now {:.3f})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="328"/>
        <source>usage {:.3f}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="364"/>
        <source>FabGuide: locked the size of {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/workbench.py" line="12"/>
        <source>Design things that work and waste nothing: functional relationships and zero-waste layouts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="85"/>
        <source>Board &apos;{}&apos;: no Source (select a sketch, a planar face or a thin solid)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="96"/>
        <source>{}: is FabGuide&apos;s {}, not a part of your model (pick a sketch, a planar face or a thin solid)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="101"/>
        <source>{}: the source has no shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="107"/>
        <source>{}: the source holds {} solids; make one board per solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="113"/>
        <source>{}: needs closed wires, a planar face or a solid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="115"/>
        <source>{}: its closed wires do not lie in one plane, so they do not outline a board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="120"/>
        <source>{}: its wires do not make a planar face ({})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="126"/>
        <source>{}: the face is not planar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="128"/>
        <source>{}: Thickness must be greater than 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="153"/>
        <source>{}: has no planar face, so it is not a flat board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="158"/>
        <source>{}: no face parallel and opposite to its largest face, so it is not a flat board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="163"/>
        <source>{}: is not a flat board of one thickness (volume {:.1f} mm3, face x thickness {:.1f} mm3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="168"/>
        <source>{}: is {:.0f} mm thick and {:.0f} mm wide, a block or a post rather than a board (a board is thinner than it is wide)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="52"/>
        <source>FreeCAD&apos;s CAM (Path) workbench is not installed: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="73"/>
        <source>tool bit file &apos;{}&apos; has no diameter ({})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="95"/>
        <source>no {} for the material &apos;{}&apos; (given for {})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="106"/>
        <source>cut through by {:g} mm: from 0 to 5 mm below the sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="110"/>
        <source>feed {:g} mm/min for &apos;{}&apos;: from 10 to 50000 mm/min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="113"/>
        <source>spindle speed {:g} rpm for &apos;{}&apos;: from 0 to 60000 rpm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="117"/>
        <source>no post-processor &apos;{}&apos; in FreeCAD (there are: {})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="121"/>
        <source>tool bit file &apos;{}&apos; not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="124"/>
        <source>Layout &apos;{}&apos;: its parts are {:g} mm apart (Kerf {:g} + Spacing {:g} mm), too close for the {:g} mm tool: set its Kerf to the tool&apos;s diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="380"/>
        <source>Job &apos;{}&apos;: post-processor &apos;{}&apos; not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/cam.py" line="392"/>
        <source>Job &apos;{}&apos;: the post-processor &apos;{}&apos; wrote nothing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="125"/>
        <source>Constraint &apos;{}&apos;: its Min ({}) is more than its Max ({})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="157"/>
        <source>Box &apos;{}&apos; is in {} &apos;{}&apos; already, and a box belongs to one group: take it out of &apos;{}&apos; first, or pick other boxes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="260"/>
        <source>constraint &apos;{}&apos;: a {} constraint takes one reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="283"/>
        <source>inner volume &apos;{}&apos;: choose the board it rests on (On)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="312"/>
        <source>add a master board (MasterBoards)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="377"/>
        <source>{}: edit undone: {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="148"/>
        <source>Layout &apos;{}&apos;: {}{}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="165"/>
        <source>{}: {} parts on {} master board(s), usage {:.1%}, sheet utilisation {:.1%}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="196"/>
        <source>Layout &apos;{}&apos;: no boards to lay out (add FabGuide boards to Boards)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="199"/>
        <source>Layout &apos;{}&apos;: no master boards (add one to MasterBoards)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="203"/>
        <source>Layout &apos;{}&apos;: board &apos;{}&apos; has no shape; recompute it first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="231"/>
        <source>Layout &apos;{}&apos;: {} lie in one plane and touch, so they are cut as one piece; set their Quantity to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="285"/>
        <source>Layout &apos;{}&apos; has not been computed yet: recompute it first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="293"/>
        <source>{} Mend that first: what was made now would show the last layout that could be made, not the boards as they are.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="25"/>
        <source>Design &apos;{}&apos;: parameter &apos;{}&apos; must read &apos;Sheet.alias min max&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="30"/>
        <source>Design &apos;{}&apos;: parameter &apos;{}&apos;: no spreadsheet &apos;{}&apos; with an alias &apos;{}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="47"/>
        <source>Spreadsheet &apos;{}&apos;: &apos;{}&apos; holds no number ({})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="77"/>
        <source>Design &apos;{}&apos; has no Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/techdraw.py" line="58"/>
        <source>TechDraw&apos;s blank A4 template is not installed with this FreeCAD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="124"/>
        <source>{}; kept {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/references.py" line="28"/>
        <source>{}; left out when opening the document
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="86"/>
        <source>see the report view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="151"/>
        <source>&apos;{0}&apos; rides on &apos;{1}&apos; by the fixed joint &apos;{2}&apos;, and a part is moved by one joint: add this joint to &apos;{1}&apos; (they move together), or delete the fixed joint and hold &apos;{1}&apos; on &apos;{0}&apos; instead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="156"/>
        <source>&apos;{}&apos; is already moved by joint &apos;{}&apos; (a part is moved by one joint): pick the part to hold first, then the part it rides on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="158"/>
        <source>&apos;{}&apos; is already moved by joint &apos;{}&apos; (a part is moved by one joint).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="97"/>
        <source>{:.1f} m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="97"/>
        <source> ({:.1f} m shared, cut once)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/core.py" line="12"/>
        <source>FabGuide&apos;s compiled core is not built for this FreeCAD (Python {}.{}){}: choose FabGuide &gt; Build the Core, or install the fabguide Debian package (README.md, Install).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/core.py" line="14"/>
        <source> (the one there does not load: {})</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="13"/>
        <source>Configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/configuration.py" line="14"/>
        <source>joints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="14"/>
        <source>Joint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="15"/>
        <source>a FabGuide part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/joints.py" line="15"/>
        <source>a FabGuide part (empty: the ground)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="24"/>
        <source>Mechanism</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="25"/>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="25"/>
        <source>a configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="217"/>
        <source>Mend the model as the note below says.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="218"/>
        <source>Change or delete one of the relationships.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="220"/>
        <source>Or unlock a box (the mechanism&apos;s Locks).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="222"/>
        <source>Or move the parts that meet apart.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="8"/>
        <source>Part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/parts.py" line="9"/>
        <source>Part::Box objects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="21"/>
        <source>Printable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/about.py" line="27"/>
        <source>About FabGuide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/about.py" line="21"/>
        <source>Show the FabGuide version and the libraries it was built with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="38"/>
        <source>this FabGuide has no sources to build from ({}): install it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="40"/>
        <source>cmake is not installed: in a terminal, run  sudo {}/tools/install-deps core</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="45"/>
        <source>the build needs Debian packages that are not installed ({}): in a terminal, run  sudo {}/tools/install-deps core</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="54"/>
        <source>the build made no fabguide_core in {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="69"/>
        <source>Building the core for this FreeCAD (Python {}.{}) in {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="108"/>
        <source>The build stopped (exit status {}): the output above names the problem.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="115"/>
        <source>The core could not be put into the workbench: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/build_core.py" line="118"/>
        <source>Built {}. Restart FreeCAD to use FabGuide.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/busy.py" line="29"/>
        <source>{}: cancelled; it keeps its last result (recompute to try again)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/busy.py" line="38"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/busy.py" line="52"/>
        <source>{}
stopping: keeping the best found so far</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/busy.py" line="61"/>
        <source>{}
{:.0f} s of at most {:.0f} s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="69"/>
        <source>Tool bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="69"/>
        <source>FreeCAD tool bits (*.fctb)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/cam_panel.py" line="78"/>
        <source>Folder for the G-code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="44"/>
        <source>{} (current)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="44"/>
        <source>New configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="85"/>
        <source>Configuration {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="114"/>
        <source>Cannot show it: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="114"/>
        <source>Moves: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="114"/>
        <source>Moves: nothing yet: tick the joints this configuration poses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="136"/>
        <source>The angle of {}: &quot;{}&quot; is not an angle from {:g} to {:g}; type it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/configurations_panel.py" line="138"/>
        <source>The offset of {}: &quot;{}&quot; is not a length from {:g} to {:g}; type it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="143"/>
        <source>Select the flat-pack design to export.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="73"/>
        <source>There is no flat-pack design in this document yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="334"/>
        <source>Select the flat-pack design.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/editing.py" line="155"/>
        <source>closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/editing.py" line="155"/>
        <source>changed by undo or redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="131"/>
        <source>Already in a part: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="304"/>
        <source>Pick boxes of at least two parts; the last one picked is the covered part.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="326"/>
        <source>Pick boxes of at least two parts; the last one picked is the enclosing part.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="340"/>
        <source>Pick boxes of at least two parts; the last one picked is the supported part.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="358"/>
        <source>Pick exactly two faces of boxes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="360"/>
        <source>Pick faces of two different boxes: two faces of one box never lie in one plane.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="375"/>
        <source>Pick one or two edges of boxes, and nothing else (a face or a whole box says no length).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="416"/>
        <source>Select the mechanism to pose.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="82"/>
        <source>There is no mechanism in this document yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="456"/>
        <source>Select the mechanism to export.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="465"/>
        <source>FabGuide wrote {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="478"/>
        <source>Select the mechanism to print.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="505"/>
        <source>Select the printable to export.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="505"/>
        <source>There is no printable in this document yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/function_commands.py" line="509"/>
        <source>Folder for the print files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="178"/>
        <source>FabGuide wrote:
  {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/layout_panel.py" line="72"/>
        <source>{}: &quot;{}&quot; is not a length from {:g} to {:g} mm; it stays {:g} mm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="96"/>
        <source>Band on the {} picked edge(s) (empty: none):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="131"/>
        <source>FabGuide: see the messages above for {}
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="165"/>
        <source>Select the layout to export.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="23"/>
        <source>There is no layout in this document yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="169"/>
        <source>Folder for the cut sheets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="192"/>
        <source>Select the layout to draw.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/relationship_panel.py" line="48"/>
        <source>&lt;br&gt;The solve changed:{}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="260"/>
        <source> (stopped)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/board.py" line="22"/>
        <source>Board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="29"/>
        <source>Design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="30"/>
        <source>master boards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="95"/>
        <source>Constraint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="27"/>
        <source> (parts squared)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="27"/>
        <source>0 or a divisor of 90 (e.g. 15, 30, 45)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="27"/>
        <source> (0: unlimited)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="27"/>
        <source>0 or more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="289"/>
        <source>Layout &apos;{}&apos; is in error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="10"/>
        <source>Master board</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="11"/>
        <source> (as many as needed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="11"/>
        <source> (an offcut you have)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/master_board.py" line="90"/>
        <source>master board &apos;{}&apos; is shared with {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="67"/>
        <source>greater than {:g}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="72"/>
        <source>{:g}{} or more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="100"/>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="135"/>
        <source>{} &apos;{}&apos;: {} must be a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/properties.py" line="140"/>
        <source>{} &apos;{}&apos;: {} must be {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/references.py" line="58"/>
        <source>{}: &apos;{}&apos; names no box (write &apos;Box label.{}&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/material_commands.py" line="214"/>
        <source>Select the layout to machine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="339"/>
        <source>Design &apos;{}&apos;: {} could not be recomputed (see the report view). Mend that first: Suggest would start from their last shapes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="289"/>
        <source>Layout &apos;{}&apos;: {} could not be recomputed (see the report view).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/parametric.py" line="34"/>
        <source>Design &apos;{}&apos;: parameter &apos;{}&apos; is {:g} now, outside its range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/design_commands.py" line="79"/>
        <source>Make a flat-pack design of the selected Part boxes (boards, their thinnest side the thickness), cut from the master boards selected with them, or a new one of their thickness; boxes drawn the same size stay so (delete the &apos;drawn equal&apos; constraints to free them); its usage updates as you edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/mechanism.py" line="175"/>
        <source>Solving &apos;{}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/function/printable.py" line="119"/>
        <source>Making the bodies of &apos;{}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="429"/>
        <source>Laying out &apos;{}&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/layout.py" line="143"/>
        <source>Laying out &apos;{}&apos; ({} boards)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/material/design.py" line="314"/>
        <source>no boxes to lay out (drag the furniture&apos;s Part boxes into the design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="64"/>
        <source>; with every board side as short as they allow, any layout of the boards needs {} sheet(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/suggest_panel.py" line="67"/>
        <source>; with every board as small as they allow it was laid out on {} sheet(s), though by their sizes they would fit on {}: more time may save one</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FabGuidePreferences</name>
    <message>
        <location filename="../ui/Preferences.ui" line="5"/>
        <source>FabGuide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="9"/>
        <source>Cutting (new layouts)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="11"/>
        <source>Kerf</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="12"/>
        <source>Width of the cut: the laser beam or the router bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="46"/>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="13"/>
        <source>Spacing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="14"/>
        <source>Material left between parts besides the kerf</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="15"/>
        <source>Edge trim</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="16"/>
        <source>Margin kept along every master board edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="17"/>
        <source>Time limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="18"/>
        <source>Seconds a layout&apos;s search may take at most</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="18"/>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="24"/>
        <source>Master board (new master boards)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="26"/>
        <source>Width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="27"/>
        <source>The sheet you buy, along the layout&apos;s x axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="28"/>
        <source>Height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="29"/>
        <source>The sheet you buy, along the layout&apos;s y axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="30"/>
        <source>Thickness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="31"/>
        <source>Used when no board gives the thickness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="37"/>
        <source>Printing in place (new printables)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="39"/>
        <source>Gap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="40"/>
        <source>Clearance between printed parts: 0.4 mm suits FDM, 0.2 mm resin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="41"/>
        <source>Build volume width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="42"/>
        <source>Your printer&apos;s build volume along x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="43"/>
        <source>Build volume depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="44"/>
        <source>Your printer&apos;s build volume along y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="45"/>
        <source>Build volume height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/Preferences.ui" line="46"/>
        <source>Your printer&apos;s build volume along z</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LayoutPanel</name>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="6"/>
        <source>Layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="12"/>
        <source>Material usage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="15"/>
        <source>Usage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="15"/>
        <source>Part area / area of the rectangle the layout covers (the thesis&apos; measure)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="26"/>
        <source>-</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="17"/>
        <source>Sheet utilisation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="17"/>
        <source>Part area / area of the master boards used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="19"/>
        <source>Waste area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="21"/>
        <source>Master boards used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="23"/>
        <source>Saw cuts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="23"/>
        <source>Guillotine cuts: how many, and their total length (the cut sequence is on the cut sheets)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="33"/>
        <source>Cutting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="36"/>
        <source>Kerf</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="38"/>
        <source>Spacing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="40"/>
        <source>Edge trim</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="42"/>
        <source>Cuts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="42"/>
        <source>Free: any outline (CNC router, laser). Guillotine: straight cuts from edge to edge only (panel, track or table saw)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="44"/>
        <source>Stages</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="44"/>
        <source>Guillotine cuts: at most this many changes of direction; 0 = unlimited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="45"/>
        <source>Unlimited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="46"/>
        <source>First cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="46"/>
        <source>Guillotine cuts: the first cuts along the sheet&apos;s length, across it, or whichever wastes less</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="25"/>
        <source>Cut length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="25"/>
        <source>Every outline and hole; with shared lines cut once, a line two boards share counted once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="48"/>
        <source>Cut shared lines once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/LayoutPanel.ui" line="48"/>
        <source>Common-line cutting: where two boards lie a kerf apart (spacing 0), the line between them is cut once, by the board cut first. The machine&apos;s paths only (not as designed)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RelationshipPanel</name>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="6"/>
        <source>Relationship</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="17"/>
        <source>Corresponding faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="22"/>
        <source>Blue → red in the 3-D view: first → second. Pick two faces there and press Add; double-click a pair to retype it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="28"/>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="28"/>
        <source>Add the two faces picked in the 3-D view as a pair</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="29"/>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="29"/>
        <source>Remove the selected pairs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="30"/>
        <source>Re-infer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/RelationshipPanel.ui" line="30"/>
        <source>Forget the pairs and infer them again on a solve</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SuggestPanel</name>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="22"/>
        <source>Suggest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="12"/>
        <source>Time limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="13"/>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="14"/>
        <source>Threads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="16"/>
        <source>Seed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="23"/>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="31"/>
        <source>Path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="36"/>
        <source>Keep these parts&apos; sizes from the suggestion:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../ui/SuggestPanel.ui" line="38"/>
        <source>Apply, keep, suggest again</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Workbench</name>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="33"/>
        <source>Parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="35"/>
        <source>Joints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="37"/>
        <source>Relationships</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="39"/>
        <source>Print in place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="41"/>
        <source>Works-like file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="43"/>
        <source>Boards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="45"/>
        <source>Cut sheets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="47"/>
        <source>Design constraints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="49"/>
        <source>Volumes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="51"/>
        <source>Flat-pack file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="56"/>
        <source>Function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="57"/>
        <source>Material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="58"/>
        <source>Zero waste</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../freecad/fabguide/gui/commands.py" line="59"/>
        <source>Zero-waste design</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
