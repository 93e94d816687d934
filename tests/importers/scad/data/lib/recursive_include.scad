// Includes itself: must end in an error, not a hang.
include <recursive_include.scad>
