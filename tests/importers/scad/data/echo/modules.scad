// Modules: children(), $children, parent_module, $ variables through module calls.
module count() { echo(children = $children); children(); }
count() { cube(); for (i = [0:2]) cube(); }
module pick() children(1);
pick() { echo("zero"); echo("one"); echo("two"); }
module sel() children([0, 2]);
sel() { echo("s0"); echo("s1"); echo("s2"); }
module rng() children([1:2]);
rng() { echo("r0"); echo("r1"); echo("r2"); }
module nest() { echo(c = $children); children(0); }
module wrap() { nest() { echo(inner = $children); } }
wrap() { cube(); cube(); }
module pm() { echo(parent_module(), parent_module(0), parent_module(1), $parent_modules); children(); }
module pn() pm() echo(pm = parent_module(0));
pn();
module fnpass() { echo(fn = $fn); sphere(); }
fnpass($fn = 12);
translate([1, 0, 0], $fn = 5) { y = $fn; echo(y = y); }
union($fn = 5) { echo(u = $fn); }
module oob() children(5);
oob() echo("never");
module neg() children(-1);
neg() echo("never");
children();
echo(top = $children);
module recurse(n) { if (n > 0) recurse(n - 1); else echo("bottom"); }
recurse(200);
for (c = "ab") echo(c);
for (x = 5) echo(x);
for (u = undef) echo(u);
for (i = [0:1], j = [5:6]) echo(i, j);
for (i = [0:9999]) echo("too many");
let(a = 1, b = a + 1) echo(a = a, b = b);
