// Placed first on the include path of the domain library only: domain/ is pure calculation and
// must not depend on JSON, HTTP or logging. Move the code that needs this header to api/ or
// service/.
#error "domain/ must not include JSON, HTTP or logging headers"
