//! Signed subresultant sequences (Sylvester–Habicht) over any exact ring, and the closed forms for quartics
