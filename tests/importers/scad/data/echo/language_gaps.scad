// Syntax and deprecated modules OpenSCAD 2021.01 accepts (compared by the echo cross-check)
// Empty elements: repeated commas in vectors, arguments and parameters
echo([8, 1.4,,"E"], [1,,,2,,,], [,], [,,], [1,,for(i=[0:1]) i]);
function f(a, b) = a + b;
echo(f(1,,2), f(,,1, 2), ,x = 5);
function g(,a,,b,,) = a * b;
h = function(,) 7;
echo(g(3, 4), h());
module m(a,,b,) echo(a, b);
m(1,, 2);
echo(let(a = 1,, b = 2) a + b, [let(,a = 1) for (i = [0,,a]) i]);
for (i = [0:1],, j = [2]) echo(i, j);
let(a = 1,, b = 2) echo(a, b);
cylinder(h=2, r1=2,, $fn=50);
// C-style list comprehension with empty init and update
k = 0;
echo([for (; k < 3; k = k + 1) k], [for (; false; ) 1]);
echo([for (,a = 0,, b = 1; a < 3; ,a = a + 1,, b = b * 2) [a, b]]);
// No-break spaces (UTF-8 and Latin-1) between tokens; kept inside strings
echo( 1 +�2, "a b");
