// A small wall in running bond on a base, one model: the parts share
// their boundary curves (a conforming mesh); each part is a physical
// surface (its material id), the bottom of the base physical line 10.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, -0.5, 0, 4, 0.5};    // base
Rectangle(2) = {0, 0, 0, 2, 0.5};       // row 1
Rectangle(3) = {2, 0, 0, 2, 0.5};
Rectangle(4) = {0, 0.5, 0, 1, 0.5};     // row 2: half, whole, half
Rectangle(5) = {1, 0.5, 0, 2, 0.5};
Rectangle(6) = {3, 0.5, 0, 1, 0.5};
Coherence;
Mesh.CharacteristicLengthMax = 0.25;
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Surface(3) = {3};
Physical Surface(4) = {4};
Physical Surface(5) = {5};
Physical Surface(6) = {6};
// bottom of the base (y = -0.5)
Physical Line(10) = {Curve In BoundingBox{-0.1, -0.6, -1, 4.1, -0.4, 1}};
