#!/bin/sh
# Writes an .mlx script for "Surface Reconstruction: HRsR" with every parameter (MeshLab 2020.09's
# meshlabserver asserts when one is missing). usage: hrsr_script.sh K METHOD [HANDLES] > script.mlx
K=${1:-70}
METHOD=${2:-0}
HANDLES=${3:--1}
cat <<XML
<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Surface Reconstruction: HRsR">
  <Param type="RichInt" name="k" value="$K"/>
  <Param type="RichDynamicFloat" name="collapse_ratio" value="0.125" min="0.01" max="1"/>
  <Param type="RichAbsPerc" name="l_min" value="0" min="0" max="1000"/>
  <Param type="RichInt" name="handles" value="$HANDLES"/>
  <Param type="RichEnum" name="method" value="$METHOD" enum_cardinality="2" enum_val0="HRsR" enum_val1="RsR"/>
  <Param type="RichInt" name="collapse_k" value="6"/>
  <Param type="RichFloat" name="theta" value="60"/>
  <Param type="RichFloat" name="r" value="20"/>
  <Param type="RichInt" name="n" value="50"/>
  <Param type="RichEnum" name="distance" value="0" enum_cardinality="2" enum_val0="Tangent" enum_val1="Euclidean"/>
  <Param type="RichEnum" name="normals" value="0" enum_cardinality="2" enum_val0="Input" enum_val1="Reestimate"/>
  <Param type="RichBool" name="select_dropped" value="true"/>
 </filter>
</FilterScript>
XML
