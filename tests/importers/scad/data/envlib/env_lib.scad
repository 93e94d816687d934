// Found through $OPENSCADPATH.
function fromenv() = "env";
