"""FabGuide GUI: the workbench, its commands, task panels and view providers."""
