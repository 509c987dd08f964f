#find the closest point
found, u, v = srf.ClosestPoint(pt)
if found:
    #get closest point
    closest_pt = srf.PointAt(u, v)
    #calculate direction from closest point to test point
    dir = pt - closest_pt
    #calculate surface normal
    normal = srf.NormalAt(u, v)
    #compare the two directions using the dot product
    A = dir * normal
