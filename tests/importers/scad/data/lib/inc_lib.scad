// Included by evaluator tests: its assignments and geometry join the including file.
size = 2;
module libcube() cube(size);
function libf() = size * 10;
echo("inc top");
