// Used by evaluator tests: only its modules and functions are visible to the user.
use <nested_use.scad>
libvar = 7;
module usedmod() echo(libvar = libvar, nested = nestedf());
function usedf(x) = x + libvar;
usedmod();
echo("use top");
