// Found through ImportOptions::libraryPaths.
function extra() = "extra";
