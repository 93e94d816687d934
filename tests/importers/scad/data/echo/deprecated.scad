// assign() and child(): deprecated in 2021.01 but still working
a = 5;
for (i = [0:2]) assign(a = i, b = a + 1) echo(a, b);
assign(c = 1, 7, $fn = 3) { c = 2; echo(c, $fn); }
assign(d = 1) cube(d);
module m() { child(); child(1); child(index = 1); child("x"); child(0.7); }
m() { echo("c0"); echo("c1"); }
module n() child(-1);
n() echo("no");
module o() child(2);
o() echo("no");
// Background parts are evaluated (their echo prints), disabled ones are not
%echo("background");
*echo("disabled");
%translate([1, 0, 0]) assign(e = 3) echo(e);
