// String and list builtins: len, str, chr, ord, concat, lookup, search.
echo(len([1, 2, 3]), len("héllo"), len([]), len(""), len(5), len([0:3]), len(undef));
echo(str("a", 1.5, [1, 2], true, undef), str(), str("x", "y"), str([["a"]]), str([0:2]));
echo(chr(65), chr([72, 105]), chr(65, 66), chr([0:2] + [1, 1, 1]), chr(233), chr(128512), chr(-1));
echo(ord("A"), ord("é"), ord("ab"), ord(""), ord(5), chr(ord("z")));
echo(concat([1, 2], [3]), concat(1, [2, [3]], "s"), concat(), concat([], []), concat([[1]], 2));
echo(lookup(5, [[0, 0], [10, 100]]), lookup(-5, [[0, 0], [10, 100]]), lookup(15, [[0, 0], [10, 100]]));
echo(lookup(2.5, [[3, 30], [1, 10], [2, 20]]), lookup(1, [[1, 5]]), lookup("a", [[1, 2]]), lookup(1, []));
echo(search("abce", "abcdabcd"), search("a", "abcdabcd", 0), search("ab", "abcdab", 2), search(3, [1, 3, 3]));
echo(search(3, [1, 3, 3], 0), search([1, 5], [1, 3, 5, 5], 0), search([1, 7], [1, 3, 5]));
echo(search("a", [["a", 1], ["b", 2]]), search([["a", 1]], [["a", 1], ["b", 2]]));
echo(search(1, [[0, 1], [1, 2]], 1, 1), search([], [1, 2]), search(undef, [1]), search("abc", [["b", 1]], 0, 0));
echo("abc"[1], "héllo"[1], [1, 2, 3][1.7], [1, 2, 3][-1], [1, 2, 3][5], [0:2:6][1], [1, 2]["a"], undef[0]);
echo([1, 2, 3].x, [1, 2, 3].y, [1, 2, 3].z, [1, 2, 3].w, [1, 2].z, [0:2:5].begin, [0:2:5].end, "abc".x);
