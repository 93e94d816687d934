// List comprehensions: for, C-style for, if/else, let, each, nesting.
echo([for (i = [0:3]) i * i], [for (i = [0:3]) if (i % 2) i else -i], [for (x = undef) x], [for (x = 5) x]);
echo([for (c = "ab") c], [each for (i = [0:1]) [i, i]], [each "ab", each [0:2], each 5, each undef]);
echo([for (i = [0:1], j = [0:1]) [i, j]], [for (i = 0, j = 1; i < 3; i = i + 1, j = j * 2) [i, j]]);
echo([for (i = [1:3]) let(a = i * 2) if (a > 2) a], [if (true) 1], [if (false) 1], [if (false) 1 else 2]);
echo([for (a = [1, 2], b = a) b], [for (i = [0:2]) for (j = [0:i]) j], [let(a = 1, b = a + 1) [a, b]]);
fs = [for (i = [0:2]) function(y) y + i];
echo(fs[0](10), fs[2](10));
echo([for (i = [0:0.1:0.35]) i], [for (i = [3:-1:1]) i], [for (i = [0:-1:3]) i], [for (i = [5:0]) i]);
echo([for (i = [0:3]) each [i]], [for (i = [0:2]) (i)], [1, for (i = [2:3]) i, 4], [for (i = []) i]);
echo([for (i = [0:1e6]) i][0]);
echo([each [[1, 2], [3]]], [for (p = [[1, 2], [3, 4]]) p[0] + p[1]], [for (i = [0:2]) if (i > 0) if (i > 1) i]);
