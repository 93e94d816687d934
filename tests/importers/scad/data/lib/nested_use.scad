// Used by use_lib.scad: visible to it, not to the files that use use_lib.scad.
function nestedf() = "nested";
