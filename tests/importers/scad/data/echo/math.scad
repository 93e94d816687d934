// Math builtins in degrees, with exact values at special angles.
echo(sin(0), sin(30), sin(45), sin(60), sin(90), sin(180), sin(270), sin(-30), sin(390), sin(1e15));
echo(cos(0), cos(60), cos(90), cos(120), cos(180), cos(720), cos(-90), tan(45), tan(90), tan(-45));
echo(tan(135), tan(270), asin(0.5), acos(-1), acos(0.5), atan(1), atan2(1, 1), atan2(0, -1), asin(2));
echo(abs(-3), abs(2.5), sign(-2), sign(0), sign(3), round(2.5), round(-2.5), round(0.49999999999999994));
echo(ceil(1.2), ceil(-1.2), floor(-1.2), floor(1.8), pow(2, 10), pow(-2, 0.5), sqrt(16), sqrt(-1));
echo(exp(1), ln(exp(2)), log(1000), log(2, 8), log(0), min(3, 1, 2), min([3, 1, 2]), max(4, 9));
echo(min(["b", "a"]), max([]), min(), min(1, "a"), min([1]), max(1), max([1, [2]]), min([1, "a"]));
echo(norm([3, 4]), norm([1, 2, 2]), norm([]), norm("a"), cross([1, 0, 0], [0, 1, 0]));
echo(cross([1, 2], [3, 4]), cross([1, 2, 3], [1, 2]), abs("x"), sin(), sin(1, 2), pow(2));
echo(rands(0, 1, 3, 42), rands(5, 1, 2, 1), rands(0, 10, 2.7, 1), rands(1, 1, 2, 3), rands(0, 1, -1, 1));
echo(rands(0, 1, 0), len(rands(0, 1, 3)), rands(-10, 10, 4, 12345));
echo(version(), version_num(), is_num(0/0), is_num(1/0), is_list([0:1]), is_function(function(x) x));
echo(is_undef(undef), is_bool(1), is_string(""), is_list([]), is_num("1"), is_bool(false));
