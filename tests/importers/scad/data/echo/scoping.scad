// OpenSCAD 2021.01 scoping rules (docs/design/openscad-subset.md sections 3 to 5).
a = 1;
echo(a = a);
a = 2;
b = c + 1;
c = 10;
echo(b = b, c = c);
x = 3;
if (true) { x = 100; echo(inner_x = x); }
echo(x = x);
module m1(p = 5, q = x * 2) echo(p = p, q = q);
m1(1);
function f(x) = x + 1;
f = function(x) x * 10;
echo(f = f(1));
module m2() echo(fn = $fn);
m2($fn = 7);
module m3() children();
m3($fn = 9) echo(fn_child = $fn);
module m4() { y = z; echo(y = y); z = 2; }
z = 1;
m4();
module m5(v) { echo(v = v); v = 5; }
m5(1);
yy = 1;
module m6(w) echo(w = w);
m6(yy) { yy = 5; }
module m7() { $q = 5; children(); }
m7() { r = $q; echo(r = r); }
module m8(a) echo(a = a, extra = bb);
m8(1, bb = 2);
function g(a, b) = [a, b];
echo(g(b = 1, 2), g(1, a = 2));
module outer() { module inner() echo("inner"); inner(); }
outer();
{ blockvar = 4; }
echo(blockvar = blockvar);
function fdef(n = a * 100) = n;
echo(fdef = fdef());
