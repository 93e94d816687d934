// Two used libraries defining the same module: the later `use` wins.
module who() echo("a");
