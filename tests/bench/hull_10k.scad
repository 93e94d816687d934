// Benchmark (scripts/bench_vs_openscad.sh): hull() of 10,000 points, the corners of 1,250 small cubes
// spread over a sphere of radius 10 (a Fibonacci spiral), so most corners are hull vertices.
n = 1250;
golden = 180 * (3 - sqrt(5));  // degrees
hull() for (i = [0 : n - 1]) {
    z = 1 - 2 * (i + 0.5) / n;
    r = sqrt(1 - z * z);
    translate(10 * [r * cos(i * golden), r * sin(i * golden), z]) cube(0.05, center=true);
}
