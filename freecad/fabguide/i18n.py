"""Translation as FreeCAD does it: each user-visible string goes through `translate("FabGuide", text)`, or is
marked with QT_TRANSLATE_NOOP where it is translated later (a command's menu text and tip); the panels' .ui texts
are Qt's own. The sources of the translations are Resources/translations/FabGuide_*.ts (`make translations`
updates them from the code), compiled to .qm files by the build; the workbench registers their folder."""
import FreeCAD

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP
