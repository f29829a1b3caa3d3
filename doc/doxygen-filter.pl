#!/usr/bin/perl
# Doxygen input filter of the 'doc' target: dealvem's comments and tutorial
# pages write inline formulas as $...$ (as deal.II's do); Doxygen wants
# @f$...@f$. Dollars already written as \f$ or @f$ are left alone.
while (<>)
  {
    s/(?<![\\@]f)\$/\@f\$/g;
    print;
  }
