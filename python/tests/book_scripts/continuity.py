#decalre variables
continuity = ""
#extract start and end points
end_c1 = c1.PointAtEnd
start_c2 = c2.PointAtStart
#check G0 continuity
if end_c1.DistanceTo(start_c2) == 0:
    continuity = "G0"
#check G1 continuity
if continuity == "G0":
    #calculate tangents
    v_c1 = c1.TangentAtEnd
    v_c2 = c2.TangentAtStart
    #unitize tangent vectors
    v_c1.Unitize()
    v_c2.Unitize()
    #compare tangents
    dot = v_c1 * v_c2
    if dot == 1:
        continuity = "G1"
#check G2 continuity
if continuity == "G1":
    #extract the parameter at start and end of the curves domain
    t1 = c1.Domain.Max
    t2 = c2.Domain.Min
    #calculate curvature
    c_c1 = c1.CurvatureAt(t1)
    c_c2 = c2.CurvatureAt(t2)
    #unitize curvature vectors
    c_c1.Unitize()
    c_c2.Unitize()
    #compare vectors
    dot = c_c1 * c_c2
    if dot == 1:
        continuity = "G2"
#assign output
A = continuity
