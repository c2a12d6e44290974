module cutcalc.example/gopeer

go 1.19
