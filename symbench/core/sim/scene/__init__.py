"""One climb's world: the MJCF model from the spec, its arena, dm-control task, index
layout, scenario and numeric set-up."""
