"""mpmFoamStudy: the modules of the speed-accuracy study tool (bin/mpmFoamStudy)."""
