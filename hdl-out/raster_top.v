

module raster_top(clock,width,height,inp$valid,inp$ready,inp$v0_x,inp$v0_y,inp$v0_z,inp$v0_c0,inp$v0_c1,inp$v0_c2,inp$v0_iw,inp$v1_x,inp$v1_y,inp$v1_z,inp$v1_c0,inp$v1_c1,inp$v1_c2,inp$v1_iw,inp$v2_x,inp$v2_y,inp$v2_z,inp$v2_c0,inp$v2_c1,inp$v2_c2,inp$v2_iw,inp_last,cull_back,verdict$valid,verdict$code,verdict$outside,mem$ready,mem$rd_en,mem$rd_addr,mem$rd_z,mem$wr_en,mem$wr_addr,mem$wr_z,mem$wr_rgb,done);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  [10:0] height;
    input wire  inp$valid;
    output wire  inp$ready;
    input wire  [15:0] inp$v0_x;
    input wire  [15:0] inp$v0_y;
    input wire  [17:0] inp$v0_z;
    input wire  [7:0] inp$v0_c0;
    input wire  [7:0] inp$v0_c1;
    input wire  [7:0] inp$v0_c2;
    input wire  [15:0] inp$v0_iw;
    input wire  [15:0] inp$v1_x;
    input wire  [15:0] inp$v1_y;
    input wire  [17:0] inp$v1_z;
    input wire  [7:0] inp$v1_c0;
    input wire  [7:0] inp$v1_c1;
    input wire  [7:0] inp$v1_c2;
    input wire  [15:0] inp$v1_iw;
    input wire  [15:0] inp$v2_x;
    input wire  [15:0] inp$v2_y;
    input wire  [17:0] inp$v2_z;
    input wire  [7:0] inp$v2_c0;
    input wire  [7:0] inp$v2_c1;
    input wire  [7:0] inp$v2_c2;
    input wire  [15:0] inp$v2_iw;
    input wire  inp_last;
    input wire  cull_back;
    output wire  verdict$valid;
    output wire  [1:0] verdict$code;
    output wire  [5:0] verdict$outside;
    input wire  mem$ready;
    output wire  mem$rd_en;
    output wire  [19:0] mem$rd_addr;
    input wire  [15:0] mem$rd_z;
    output wire  mem$wr_en;
    output wire  [19:0] mem$wr_addr;
    output wire  [15:0] mem$wr_z;
    output wire  [23:0] mem$wr_rgb;
    output reg  done;
    
    // Stub signals
    reg  fragments$clock;
    reg  [10:0] fragments$width;
    reg  [10:0] fragments$height;
    reg  fragments$inp_last;
    reg  fragments$cull_back;
    wire  fragments$out$valid;
    reg  fragments$out$ready;
    wire  [9:0] fragments$out$x;
    wire  [9:0] fragments$out$y;
    wire  [15:0] fragments$out$z;
    wire  [7:0] fragments$out$rgb0;
    wire  [7:0] fragments$out$rgb1;
    wire  [7:0] fragments$out$rgb2;
    wire  fragments$done;
    reg  pixel_out$clock;
    reg  pixel_out$inp$valid;
    wire  pixel_out$inp$ready;
    reg  [9:0] pixel_out$inp$x;
    reg  [9:0] pixel_out$inp$y;
    reg  [15:0] pixel_out$inp$z;
    reg  [7:0] pixel_out$inp$rgb0;
    reg  [7:0] pixel_out$inp$rgb1;
    reg  [7:0] pixel_out$inp$rgb2;
    wire  pixel_out$idle;
    
    // Sub module instances
    raster_top$fragments fragments(
        .clock(fragments$clock),
        .width(fragments$width),
        .height(fragments$height),
        .inp$valid(inp$valid),
        .inp$ready(inp$ready),
        .inp$v0_x(inp$v0_x),
        .inp$v0_y(inp$v0_y),
        .inp$v0_z(inp$v0_z),
        .inp$v0_c0(inp$v0_c0),
        .inp$v0_c1(inp$v0_c1),
        .inp$v0_c2(inp$v0_c2),
        .inp$v0_iw(inp$v0_iw),
        .inp$v1_x(inp$v1_x),
        .inp$v1_y(inp$v1_y),
        .inp$v1_z(inp$v1_z),
        .inp$v1_c0(inp$v1_c0),
        .inp$v1_c1(inp$v1_c1),
        .inp$v1_c2(inp$v1_c2),
        .inp$v1_iw(inp$v1_iw),
        .inp$v2_x(inp$v2_x),
        .inp$v2_y(inp$v2_y),
        .inp$v2_z(inp$v2_z),
        .inp$v2_c0(inp$v2_c0),
        .inp$v2_c1(inp$v2_c1),
        .inp$v2_c2(inp$v2_c2),
        .inp$v2_iw(inp$v2_iw),
        .inp_last(fragments$inp_last),
        .cull_back(fragments$cull_back),
        .verdict$valid(verdict$valid),
        .verdict$code(verdict$code),
        .verdict$outside(verdict$outside),
        .out$valid(fragments$out$valid),
        .out$ready(fragments$out$ready),
        .out$x(fragments$out$x),
        .out$y(fragments$out$y),
        .out$z(fragments$out$z),
        .out$rgb0(fragments$out$rgb0),
        .out$rgb1(fragments$out$rgb1),
        .out$rgb2(fragments$out$rgb2),
        .done(fragments$done)
    );
    raster_top$pixel_out pixel_out(
        .clock(pixel_out$clock),
        .inp$valid(pixel_out$inp$valid),
        .inp$ready(pixel_out$inp$ready),
        .inp$x(pixel_out$inp$x),
        .inp$y(pixel_out$inp$y),
        .inp$z(pixel_out$inp$z),
        .inp$rgb0(pixel_out$inp$rgb0),
        .inp$rgb1(pixel_out$inp$rgb1),
        .inp$rgb2(pixel_out$inp$rgb2),
        .mem$ready(mem$ready),
        .mem$rd_en(mem$rd_en),
        .mem$rd_addr(mem$rd_addr),
        .mem$rd_z(mem$rd_z),
        .mem$wr_en(mem$wr_en),
        .mem$wr_addr(mem$wr_addr),
        .mem$wr_z(mem$wr_z),
        .mem$wr_rgb(mem$wr_rgb),
        .idle(pixel_out$idle)
    );
    
    // Update code
    always @(*) begin
        fragments$clock = clock;
        pixel_out$clock = clock;
        fragments$width = width;
        fragments$height = height;
        fragments$inp_last = inp_last;
        fragments$cull_back = cull_back;
        done = fragments$done & pixel_out$idle;
    end
    
    always @(*) pixel_out$inp$valid = fragments$out$valid;
    always @(*) fragments$out$ready = pixel_out$inp$ready;
    always @(*) pixel_out$inp$x = fragments$out$x;
    always @(*) pixel_out$inp$y = fragments$out$y;
    always @(*) pixel_out$inp$z = fragments$out$z;
    always @(*) pixel_out$inp$rgb0 = fragments$out$rgb0;
    always @(*) pixel_out$inp$rgb1 = fragments$out$rgb1;
    always @(*) pixel_out$inp$rgb2 = fragments$out$rgb2;
endmodule // raster_top


module raster_top$fragments(clock,width,height,inp$valid,inp$ready,inp$v0_x,inp$v0_y,inp$v0_z,inp$v0_c0,inp$v0_c1,inp$v0_c2,inp$v0_iw,inp$v1_x,inp$v1_y,inp$v1_z,inp$v1_c0,inp$v1_c1,inp$v1_c2,inp$v1_iw,inp$v2_x,inp$v2_y,inp$v2_z,inp$v2_c0,inp$v2_c1,inp$v2_c2,inp$v2_iw,inp_last,cull_back,verdict$valid,verdict$code,verdict$outside,out$valid,out$ready,out$x,out$y,out$z,out$rgb0,out$rgb1,out$rgb2,done);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  [10:0] height;
    input wire  inp$valid;
    output wire  inp$ready;
    input wire  [15:0] inp$v0_x;
    input wire  [15:0] inp$v0_y;
    input wire  [17:0] inp$v0_z;
    input wire  [7:0] inp$v0_c0;
    input wire  [7:0] inp$v0_c1;
    input wire  [7:0] inp$v0_c2;
    input wire  [15:0] inp$v0_iw;
    input wire  [15:0] inp$v1_x;
    input wire  [15:0] inp$v1_y;
    input wire  [17:0] inp$v1_z;
    input wire  [7:0] inp$v1_c0;
    input wire  [7:0] inp$v1_c1;
    input wire  [7:0] inp$v1_c2;
    input wire  [15:0] inp$v1_iw;
    input wire  [15:0] inp$v2_x;
    input wire  [15:0] inp$v2_y;
    input wire  [17:0] inp$v2_z;
    input wire  [7:0] inp$v2_c0;
    input wire  [7:0] inp$v2_c1;
    input wire  [7:0] inp$v2_c2;
    input wire  [15:0] inp$v2_iw;
    input wire  inp_last;
    input wire  cull_back;
    output wire  verdict$valid;
    output wire  [1:0] verdict$code;
    output wire  [5:0] verdict$outside;
    output wire  out$valid;
    input wire  out$ready;
    output wire  [9:0] out$x;
    output wire  [9:0] out$y;
    output wire  [15:0] out$z;
    output wire  [7:0] out$rgb0;
    output wire  [7:0] out$rgb1;
    output wire  [7:0] out$rgb2;
    output reg  done;
    
    // Stub signals
    reg  cull_sort$clock;
    reg  [10:0] cull_sort$width;
    reg  [10:0] cull_sort$height;
    reg  cull_sort$cull_back;
    wire  cull_sort$out$valid;
    reg  cull_sort$out$ready;
    wire  [15:0] cull_sort$out$v0_x;
    wire  [15:0] cull_sort$out$v0_y;
    wire  [17:0] cull_sort$out$v0_z;
    wire  [7:0] cull_sort$out$v0_c0;
    wire  [7:0] cull_sort$out$v0_c1;
    wire  [7:0] cull_sort$out$v0_c2;
    wire  [15:0] cull_sort$out$v0_iw;
    wire  [15:0] cull_sort$out$v1_x;
    wire  [15:0] cull_sort$out$v1_y;
    wire  [17:0] cull_sort$out$v1_z;
    wire  [7:0] cull_sort$out$v1_c0;
    wire  [7:0] cull_sort$out$v1_c1;
    wire  [7:0] cull_sort$out$v1_c2;
    wire  [15:0] cull_sort$out$v1_iw;
    wire  [15:0] cull_sort$out$v2_x;
    wire  [15:0] cull_sort$out$v2_y;
    wire  [17:0] cull_sort$out$v2_z;
    wire  [7:0] cull_sort$out$v2_c0;
    wire  [7:0] cull_sort$out$v2_c1;
    wire  [7:0] cull_sort$out$v2_c2;
    wire  [15:0] cull_sort$out$v2_iw;
    wire  [5:0] cull_sort$out$crosses;
    wire  cull_sort$idle;
    reg  core$clock;
    reg  [10:0] core$width;
    reg  [10:0] core$height;
    reg  core$inp$valid;
    wire  core$inp$ready;
    reg  [15:0] core$inp$v0_x;
    reg  [15:0] core$inp$v0_y;
    reg  [17:0] core$inp$v0_z;
    reg  [7:0] core$inp$v0_c0;
    reg  [7:0] core$inp$v0_c1;
    reg  [7:0] core$inp$v0_c2;
    reg  [15:0] core$inp$v0_iw;
    reg  [15:0] core$inp$v1_x;
    reg  [15:0] core$inp$v1_y;
    reg  [17:0] core$inp$v1_z;
    reg  [7:0] core$inp$v1_c0;
    reg  [7:0] core$inp$v1_c1;
    reg  [7:0] core$inp$v1_c2;
    reg  [15:0] core$inp$v1_iw;
    reg  [15:0] core$inp$v2_x;
    reg  [15:0] core$inp$v2_y;
    reg  [17:0] core$inp$v2_z;
    reg  [7:0] core$inp$v2_c0;
    reg  [7:0] core$inp$v2_c1;
    reg  [7:0] core$inp$v2_c2;
    reg  [15:0] core$inp$v2_iw;
    reg  [5:0] core$inp$crosses;
    reg  core$inp_last;
    wire  core$idle;
    wire  core$done;
    reg  core$hold;
    wire  core$handed;
    wire  [24:0] core$recip_mant;
    wire  [5:0] core$recip_exp;
    wire  core$walk_idle;
    reg  last_in$d;
    wire  last_in$q;
    reg  last_in$clock;
    
    // Sub module instances
    raster_top$fragments$cull_sort cull_sort(
        .clock(cull_sort$clock),
        .width(cull_sort$width),
        .height(cull_sort$height),
        .cull_back(cull_sort$cull_back),
        .inp$valid(inp$valid),
        .inp$ready(inp$ready),
        .inp$v0_x(inp$v0_x),
        .inp$v0_y(inp$v0_y),
        .inp$v0_z(inp$v0_z),
        .inp$v0_c0(inp$v0_c0),
        .inp$v0_c1(inp$v0_c1),
        .inp$v0_c2(inp$v0_c2),
        .inp$v0_iw(inp$v0_iw),
        .inp$v1_x(inp$v1_x),
        .inp$v1_y(inp$v1_y),
        .inp$v1_z(inp$v1_z),
        .inp$v1_c0(inp$v1_c0),
        .inp$v1_c1(inp$v1_c1),
        .inp$v1_c2(inp$v1_c2),
        .inp$v1_iw(inp$v1_iw),
        .inp$v2_x(inp$v2_x),
        .inp$v2_y(inp$v2_y),
        .inp$v2_z(inp$v2_z),
        .inp$v2_c0(inp$v2_c0),
        .inp$v2_c1(inp$v2_c1),
        .inp$v2_c2(inp$v2_c2),
        .inp$v2_iw(inp$v2_iw),
        .out$valid(cull_sort$out$valid),
        .out$ready(cull_sort$out$ready),
        .out$v0_x(cull_sort$out$v0_x),
        .out$v0_y(cull_sort$out$v0_y),
        .out$v0_z(cull_sort$out$v0_z),
        .out$v0_c0(cull_sort$out$v0_c0),
        .out$v0_c1(cull_sort$out$v0_c1),
        .out$v0_c2(cull_sort$out$v0_c2),
        .out$v0_iw(cull_sort$out$v0_iw),
        .out$v1_x(cull_sort$out$v1_x),
        .out$v1_y(cull_sort$out$v1_y),
        .out$v1_z(cull_sort$out$v1_z),
        .out$v1_c0(cull_sort$out$v1_c0),
        .out$v1_c1(cull_sort$out$v1_c1),
        .out$v1_c2(cull_sort$out$v1_c2),
        .out$v1_iw(cull_sort$out$v1_iw),
        .out$v2_x(cull_sort$out$v2_x),
        .out$v2_y(cull_sort$out$v2_y),
        .out$v2_z(cull_sort$out$v2_z),
        .out$v2_c0(cull_sort$out$v2_c0),
        .out$v2_c1(cull_sort$out$v2_c1),
        .out$v2_c2(cull_sort$out$v2_c2),
        .out$v2_iw(cull_sort$out$v2_iw),
        .out$crosses(cull_sort$out$crosses),
        .verdict$valid(verdict$valid),
        .verdict$code(verdict$code),
        .verdict$outside(verdict$outside),
        .idle(cull_sort$idle)
    );
    raster_top$fragments$core core(
        .clock(core$clock),
        .width(core$width),
        .height(core$height),
        .inp$valid(core$inp$valid),
        .inp$ready(core$inp$ready),
        .inp$v0_x(core$inp$v0_x),
        .inp$v0_y(core$inp$v0_y),
        .inp$v0_z(core$inp$v0_z),
        .inp$v0_c0(core$inp$v0_c0),
        .inp$v0_c1(core$inp$v0_c1),
        .inp$v0_c2(core$inp$v0_c2),
        .inp$v0_iw(core$inp$v0_iw),
        .inp$v1_x(core$inp$v1_x),
        .inp$v1_y(core$inp$v1_y),
        .inp$v1_z(core$inp$v1_z),
        .inp$v1_c0(core$inp$v1_c0),
        .inp$v1_c1(core$inp$v1_c1),
        .inp$v1_c2(core$inp$v1_c2),
        .inp$v1_iw(core$inp$v1_iw),
        .inp$v2_x(core$inp$v2_x),
        .inp$v2_y(core$inp$v2_y),
        .inp$v2_z(core$inp$v2_z),
        .inp$v2_c0(core$inp$v2_c0),
        .inp$v2_c1(core$inp$v2_c1),
        .inp$v2_c2(core$inp$v2_c2),
        .inp$v2_iw(core$inp$v2_iw),
        .inp$crosses(core$inp$crosses),
        .inp_last(core$inp_last),
        .out$valid(out$valid),
        .out$ready(out$ready),
        .out$x(out$x),
        .out$y(out$y),
        .out$z(out$z),
        .out$rgb0(out$rgb0),
        .out$rgb1(out$rgb1),
        .out$rgb2(out$rgb2),
        .idle(core$idle),
        .done(core$done),
        .hold(core$hold),
        .handed(core$handed),
        .recip_mant(core$recip_mant),
        .recip_exp(core$recip_exp),
        .walk_idle(core$walk_idle)
    );
    raster_top$fragments$last_in last_in(
        .d(last_in$d),
        .q(last_in$q),
        .clock(last_in$clock)
    );
    
    // Update code
    always @(*) begin
        last_in$clock = clock;
        last_in$d = last_in$q;
        cull_sort$clock = clock;
        core$clock = clock;
        cull_sort$width = width;
        cull_sort$height = height;
        cull_sort$cull_back = cull_back;
        core$width = width;
        core$height = height;
        core$inp_last = 1'b0;
        core$hold = 1'b0;
        if (inp$valid & inp$ready) begin
            last_in$d = inp_last;
        end
        done = last_in$q & cull_sort$idle & core$idle;
    end
    
    always @(*) core$inp$valid = cull_sort$out$valid;
    always @(*) cull_sort$out$ready = core$inp$ready;
    always @(*) core$inp$v0_x = cull_sort$out$v0_x;
    always @(*) core$inp$v0_y = cull_sort$out$v0_y;
    always @(*) core$inp$v0_z = cull_sort$out$v0_z;
    always @(*) core$inp$v0_c0 = cull_sort$out$v0_c0;
    always @(*) core$inp$v0_c1 = cull_sort$out$v0_c1;
    always @(*) core$inp$v0_c2 = cull_sort$out$v0_c2;
    always @(*) core$inp$v0_iw = cull_sort$out$v0_iw;
    always @(*) core$inp$v1_x = cull_sort$out$v1_x;
    always @(*) core$inp$v1_y = cull_sort$out$v1_y;
    always @(*) core$inp$v1_z = cull_sort$out$v1_z;
    always @(*) core$inp$v1_c0 = cull_sort$out$v1_c0;
    always @(*) core$inp$v1_c1 = cull_sort$out$v1_c1;
    always @(*) core$inp$v1_c2 = cull_sort$out$v1_c2;
    always @(*) core$inp$v1_iw = cull_sort$out$v1_iw;
    always @(*) core$inp$v2_x = cull_sort$out$v2_x;
    always @(*) core$inp$v2_y = cull_sort$out$v2_y;
    always @(*) core$inp$v2_z = cull_sort$out$v2_z;
    always @(*) core$inp$v2_c0 = cull_sort$out$v2_c0;
    always @(*) core$inp$v2_c1 = cull_sort$out$v2_c1;
    always @(*) core$inp$v2_c2 = cull_sort$out$v2_c2;
    always @(*) core$inp$v2_iw = cull_sort$out$v2_iw;
    always @(*) core$inp$crosses = cull_sort$out$crosses;
endmodule // raster_top$fragments


module raster_top$fragments$core(clock,width,height,inp$valid,inp$ready,inp$v0_x,inp$v0_y,inp$v0_z,inp$v0_c0,inp$v0_c1,inp$v0_c2,inp$v0_iw,inp$v1_x,inp$v1_y,inp$v1_z,inp$v1_c0,inp$v1_c1,inp$v1_c2,inp$v1_iw,inp$v2_x,inp$v2_y,inp$v2_z,inp$v2_c0,inp$v2_c1,inp$v2_c2,inp$v2_iw,inp$crosses,inp_last,out$valid,out$ready,out$x,out$y,out$z,out$rgb0,out$rgb1,out$rgb2,idle,done,hold,handed,recip_mant,recip_exp,walk_idle);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  [10:0] height;
    input wire  inp$valid;
    output wire  inp$ready;
    input wire  [15:0] inp$v0_x;
    input wire  [15:0] inp$v0_y;
    input wire  [17:0] inp$v0_z;
    input wire  [7:0] inp$v0_c0;
    input wire  [7:0] inp$v0_c1;
    input wire  [7:0] inp$v0_c2;
    input wire  [15:0] inp$v0_iw;
    input wire  [15:0] inp$v1_x;
    input wire  [15:0] inp$v1_y;
    input wire  [17:0] inp$v1_z;
    input wire  [7:0] inp$v1_c0;
    input wire  [7:0] inp$v1_c1;
    input wire  [7:0] inp$v1_c2;
    input wire  [15:0] inp$v1_iw;
    input wire  [15:0] inp$v2_x;
    input wire  [15:0] inp$v2_y;
    input wire  [17:0] inp$v2_z;
    input wire  [7:0] inp$v2_c0;
    input wire  [7:0] inp$v2_c1;
    input wire  [7:0] inp$v2_c2;
    input wire  [15:0] inp$v2_iw;
    input wire  [5:0] inp$crosses;
    input wire  inp_last;
    output wire  out$valid;
    input wire  out$ready;
    output wire  [9:0] out$x;
    output wire  [9:0] out$y;
    output wire  [15:0] out$z;
    output wire  [7:0] out$rgb0;
    output wire  [7:0] out$rgb1;
    output wire  [7:0] out$rgb2;
    output reg  idle;
    output reg  done;
    input wire  hold;
    output reg  handed;
    output reg  [24:0] recip_mant;
    output reg  [5:0] recip_exp;
    output reg  walk_idle;
    
    // Stub signals
    reg  triangle_setup$clock;
    wire  triangle_setup$out$valid;
    reg  triangle_setup$out$ready;
    wire  triangle_setup$out$walk;
    wire  triangle_setup$out$maj_left;
    wire  [12:0] triangle_setup$out$maj_j;
    wire  [12:0] triangle_setup$out$maj_count;
    wire  [12:0] triangle_setup$out$maj_x;
    wire  [20:0] triangle_setup$out$maj_r;
    wire  [16:0] triangle_setup$out$maj_q;
    wire  [20:0] triangle_setup$out$maj_rho;
    wire  [20:0] triangle_setup$out$maj_d;
    wire  [35:0] triangle_setup$out$maj_at_z;
    wire  [31:0] triangle_setup$out$maj_at_c0;
    wire  [31:0] triangle_setup$out$maj_at_c1;
    wire  [31:0] triangle_setup$out$maj_at_c2;
    wire  [39:0] triangle_setup$out$maj_inc0_z;
    wire  [35:0] triangle_setup$out$maj_inc0_c0;
    wire  [35:0] triangle_setup$out$maj_inc0_c1;
    wire  [35:0] triangle_setup$out$maj_inc0_c2;
    wire  [39:0] triangle_setup$out$maj_inc1_z;
    wire  [35:0] triangle_setup$out$maj_inc1_c0;
    wire  [35:0] triangle_setup$out$maj_inc1_c1;
    wire  [35:0] triangle_setup$out$maj_inc1_c2;
    wire  [12:0] triangle_setup$out$short0_j;
    wire  [12:0] triangle_setup$out$short0_count;
    wire  [12:0] triangle_setup$out$short0_x;
    wire  [20:0] triangle_setup$out$short0_r;
    wire  [16:0] triangle_setup$out$short0_q;
    wire  [20:0] triangle_setup$out$short0_rho;
    wire  [20:0] triangle_setup$out$short0_d;
    wire  [35:0] triangle_setup$out$short0_at_z;
    wire  [31:0] triangle_setup$out$short0_at_c0;
    wire  [31:0] triangle_setup$out$short0_at_c1;
    wire  [31:0] triangle_setup$out$short0_at_c2;
    wire  [39:0] triangle_setup$out$short0_inc0_z;
    wire  [35:0] triangle_setup$out$short0_inc0_c0;
    wire  [35:0] triangle_setup$out$short0_inc0_c1;
    wire  [35:0] triangle_setup$out$short0_inc0_c2;
    wire  [39:0] triangle_setup$out$short0_inc1_z;
    wire  [35:0] triangle_setup$out$short0_inc1_c0;
    wire  [35:0] triangle_setup$out$short0_inc1_c1;
    wire  [35:0] triangle_setup$out$short0_inc1_c2;
    wire  [12:0] triangle_setup$out$short1_j;
    wire  [12:0] triangle_setup$out$short1_count;
    wire  [12:0] triangle_setup$out$short1_x;
    wire  [20:0] triangle_setup$out$short1_r;
    wire  [16:0] triangle_setup$out$short1_q;
    wire  [20:0] triangle_setup$out$short1_rho;
    wire  [20:0] triangle_setup$out$short1_d;
    wire  [35:0] triangle_setup$out$short1_at_z;
    wire  [31:0] triangle_setup$out$short1_at_c0;
    wire  [31:0] triangle_setup$out$short1_at_c1;
    wire  [31:0] triangle_setup$out$short1_at_c2;
    wire  [39:0] triangle_setup$out$short1_inc0_z;
    wire  [35:0] triangle_setup$out$short1_inc0_c0;
    wire  [35:0] triangle_setup$out$short1_inc0_c1;
    wire  [35:0] triangle_setup$out$short1_inc0_c2;
    wire  [39:0] triangle_setup$out$short1_inc1_z;
    wire  [35:0] triangle_setup$out$short1_inc1_c0;
    wire  [35:0] triangle_setup$out$short1_inc1_c1;
    wire  [35:0] triangle_setup$out$short1_inc1_c2;
    wire  [39:0] triangle_setup$out$ddx_z;
    wire  [35:0] triangle_setup$out$ddx_c0;
    wire  [35:0] triangle_setup$out$ddx_c1;
    wire  [35:0] triangle_setup$out$ddx_c2;
    wire  [24:0] triangle_setup$recip_mant;
    wire  [5:0] triangle_setup$recip_exp;
    wire  triangle_setup$idle;
    reg  triangle_setup$out_free_next;
    reg  triangle_setup$out_hold;
    reg  edge_walk$clock;
    reg  [10:0] edge_walk$height;
    reg  edge_walk$inp$valid;
    wire  edge_walk$inp$ready;
    reg  edge_walk$inp$walk;
    reg  edge_walk$inp$maj_left;
    reg  [12:0] edge_walk$inp$maj_j;
    reg  [12:0] edge_walk$inp$maj_count;
    reg  [12:0] edge_walk$inp$maj_x;
    reg  [20:0] edge_walk$inp$maj_r;
    reg  [16:0] edge_walk$inp$maj_q;
    reg  [20:0] edge_walk$inp$maj_rho;
    reg  [20:0] edge_walk$inp$maj_d;
    reg  [35:0] edge_walk$inp$maj_at_z;
    reg  [31:0] edge_walk$inp$maj_at_c0;
    reg  [31:0] edge_walk$inp$maj_at_c1;
    reg  [31:0] edge_walk$inp$maj_at_c2;
    reg  [39:0] edge_walk$inp$maj_inc0_z;
    reg  [35:0] edge_walk$inp$maj_inc0_c0;
    reg  [35:0] edge_walk$inp$maj_inc0_c1;
    reg  [35:0] edge_walk$inp$maj_inc0_c2;
    reg  [39:0] edge_walk$inp$maj_inc1_z;
    reg  [35:0] edge_walk$inp$maj_inc1_c0;
    reg  [35:0] edge_walk$inp$maj_inc1_c1;
    reg  [35:0] edge_walk$inp$maj_inc1_c2;
    reg  [12:0] edge_walk$inp$short0_j;
    reg  [12:0] edge_walk$inp$short0_count;
    reg  [12:0] edge_walk$inp$short0_x;
    reg  [20:0] edge_walk$inp$short0_r;
    reg  [16:0] edge_walk$inp$short0_q;
    reg  [20:0] edge_walk$inp$short0_rho;
    reg  [20:0] edge_walk$inp$short0_d;
    reg  [35:0] edge_walk$inp$short0_at_z;
    reg  [31:0] edge_walk$inp$short0_at_c0;
    reg  [31:0] edge_walk$inp$short0_at_c1;
    reg  [31:0] edge_walk$inp$short0_at_c2;
    reg  [39:0] edge_walk$inp$short0_inc0_z;
    reg  [35:0] edge_walk$inp$short0_inc0_c0;
    reg  [35:0] edge_walk$inp$short0_inc0_c1;
    reg  [35:0] edge_walk$inp$short0_inc0_c2;
    reg  [39:0] edge_walk$inp$short0_inc1_z;
    reg  [35:0] edge_walk$inp$short0_inc1_c0;
    reg  [35:0] edge_walk$inp$short0_inc1_c1;
    reg  [35:0] edge_walk$inp$short0_inc1_c2;
    reg  [12:0] edge_walk$inp$short1_j;
    reg  [12:0] edge_walk$inp$short1_count;
    reg  [12:0] edge_walk$inp$short1_x;
    reg  [20:0] edge_walk$inp$short1_r;
    reg  [16:0] edge_walk$inp$short1_q;
    reg  [20:0] edge_walk$inp$short1_rho;
    reg  [20:0] edge_walk$inp$short1_d;
    reg  [35:0] edge_walk$inp$short1_at_z;
    reg  [31:0] edge_walk$inp$short1_at_c0;
    reg  [31:0] edge_walk$inp$short1_at_c1;
    reg  [31:0] edge_walk$inp$short1_at_c2;
    reg  [39:0] edge_walk$inp$short1_inc0_z;
    reg  [35:0] edge_walk$inp$short1_inc0_c0;
    reg  [35:0] edge_walk$inp$short1_inc0_c1;
    reg  [35:0] edge_walk$inp$short1_inc0_c2;
    reg  [39:0] edge_walk$inp$short1_inc1_z;
    reg  [35:0] edge_walk$inp$short1_inc1_c0;
    reg  [35:0] edge_walk$inp$short1_inc1_c1;
    reg  [35:0] edge_walk$inp$short1_inc1_c2;
    reg  [39:0] edge_walk$inp$ddx_z;
    reg  [35:0] edge_walk$inp$ddx_c0;
    reg  [35:0] edge_walk$inp$ddx_c1;
    reg  [35:0] edge_walk$inp$ddx_c2;
    wire  edge_walk$out$valid;
    reg  edge_walk$out$ready;
    wire  [9:0] edge_walk$out$y;
    wire  [12:0] edge_walk$out$xl;
    wire  [12:0] edge_walk$out$xr;
    wire  [35:0] edge_walk$out$left_z;
    wire  [31:0] edge_walk$out$left_c0;
    wire  [31:0] edge_walk$out$left_c1;
    wire  [31:0] edge_walk$out$left_c2;
    wire  [35:0] edge_walk$out$right_z;
    wire  [31:0] edge_walk$out$right_c0;
    wire  [31:0] edge_walk$out$right_c1;
    wire  [31:0] edge_walk$out$right_c2;
    wire  [39:0] edge_walk$out$ddx_z;
    wire  [35:0] edge_walk$out$ddx_c0;
    wire  [35:0] edge_walk$out$ddx_c1;
    wire  [35:0] edge_walk$out$ddx_c2;
    reg  edge_walk$hold;
    wire  edge_walk$idle;
    wire  edge_walk$free_next;
    reg  fifo$clock;
    reg  fifo$inp$valid;
    wire  fifo$inp$ready;
    reg  [9:0] fifo$inp$y;
    reg  [12:0] fifo$inp$xl;
    reg  [12:0] fifo$inp$xr;
    reg  [35:0] fifo$inp$left_z;
    reg  [31:0] fifo$inp$left_c0;
    reg  [31:0] fifo$inp$left_c1;
    reg  [31:0] fifo$inp$left_c2;
    reg  [35:0] fifo$inp$right_z;
    reg  [31:0] fifo$inp$right_c0;
    reg  [31:0] fifo$inp$right_c1;
    reg  [31:0] fifo$inp$right_c2;
    reg  [39:0] fifo$inp$ddx_z;
    reg  [35:0] fifo$inp$ddx_c0;
    reg  [35:0] fifo$inp$ddx_c1;
    reg  [35:0] fifo$inp$ddx_c2;
    wire  fifo$out$valid;
    reg  fifo$out$ready;
    wire  [9:0] fifo$out$y;
    wire  [12:0] fifo$out$xl;
    wire  [12:0] fifo$out$xr;
    wire  [35:0] fifo$out$left_z;
    wire  [31:0] fifo$out$left_c0;
    wire  [31:0] fifo$out$left_c1;
    wire  [31:0] fifo$out$left_c2;
    wire  [35:0] fifo$out$right_z;
    wire  [31:0] fifo$out$right_c0;
    wire  [31:0] fifo$out$right_c1;
    wire  [31:0] fifo$out$right_c2;
    wire  [39:0] fifo$out$ddx_z;
    wire  [35:0] fifo$out$ddx_c0;
    wire  [35:0] fifo$out$ddx_c1;
    wire  [35:0] fifo$out$ddx_c2;
    wire  fifo$empty;
    reg  span$clock;
    reg  [10:0] span$width;
    reg  span$inp$valid;
    wire  span$inp$ready;
    reg  [9:0] span$inp$y;
    reg  [12:0] span$inp$xl;
    reg  [12:0] span$inp$xr;
    reg  [35:0] span$inp$left_z;
    reg  [31:0] span$inp$left_c0;
    reg  [31:0] span$inp$left_c1;
    reg  [31:0] span$inp$left_c2;
    reg  [35:0] span$inp$right_z;
    reg  [31:0] span$inp$right_c0;
    reg  [31:0] span$inp$right_c1;
    reg  [31:0] span$inp$right_c2;
    reg  [39:0] span$inp$ddx_z;
    reg  [35:0] span$inp$ddx_c0;
    reg  [35:0] span$inp$ddx_c1;
    reg  [35:0] span$inp$ddx_c2;
    wire  span$idle;
    reg  last_in$d;
    wire  last_in$q;
    reg  last_in$clock;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup triangle_setup(
        .clock(triangle_setup$clock),
        .inp$valid(inp$valid),
        .inp$ready(inp$ready),
        .inp$v0_x(inp$v0_x),
        .inp$v0_y(inp$v0_y),
        .inp$v0_z(inp$v0_z),
        .inp$v0_c0(inp$v0_c0),
        .inp$v0_c1(inp$v0_c1),
        .inp$v0_c2(inp$v0_c2),
        .inp$v0_iw(inp$v0_iw),
        .inp$v1_x(inp$v1_x),
        .inp$v1_y(inp$v1_y),
        .inp$v1_z(inp$v1_z),
        .inp$v1_c0(inp$v1_c0),
        .inp$v1_c1(inp$v1_c1),
        .inp$v1_c2(inp$v1_c2),
        .inp$v1_iw(inp$v1_iw),
        .inp$v2_x(inp$v2_x),
        .inp$v2_y(inp$v2_y),
        .inp$v2_z(inp$v2_z),
        .inp$v2_c0(inp$v2_c0),
        .inp$v2_c1(inp$v2_c1),
        .inp$v2_c2(inp$v2_c2),
        .inp$v2_iw(inp$v2_iw),
        .inp$crosses(inp$crosses),
        .out$valid(triangle_setup$out$valid),
        .out$ready(triangle_setup$out$ready),
        .out$walk(triangle_setup$out$walk),
        .out$maj_left(triangle_setup$out$maj_left),
        .out$maj_j(triangle_setup$out$maj_j),
        .out$maj_count(triangle_setup$out$maj_count),
        .out$maj_x(triangle_setup$out$maj_x),
        .out$maj_r(triangle_setup$out$maj_r),
        .out$maj_q(triangle_setup$out$maj_q),
        .out$maj_rho(triangle_setup$out$maj_rho),
        .out$maj_d(triangle_setup$out$maj_d),
        .out$maj_at_z(triangle_setup$out$maj_at_z),
        .out$maj_at_c0(triangle_setup$out$maj_at_c0),
        .out$maj_at_c1(triangle_setup$out$maj_at_c1),
        .out$maj_at_c2(triangle_setup$out$maj_at_c2),
        .out$maj_inc0_z(triangle_setup$out$maj_inc0_z),
        .out$maj_inc0_c0(triangle_setup$out$maj_inc0_c0),
        .out$maj_inc0_c1(triangle_setup$out$maj_inc0_c1),
        .out$maj_inc0_c2(triangle_setup$out$maj_inc0_c2),
        .out$maj_inc1_z(triangle_setup$out$maj_inc1_z),
        .out$maj_inc1_c0(triangle_setup$out$maj_inc1_c0),
        .out$maj_inc1_c1(triangle_setup$out$maj_inc1_c1),
        .out$maj_inc1_c2(triangle_setup$out$maj_inc1_c2),
        .out$short0_j(triangle_setup$out$short0_j),
        .out$short0_count(triangle_setup$out$short0_count),
        .out$short0_x(triangle_setup$out$short0_x),
        .out$short0_r(triangle_setup$out$short0_r),
        .out$short0_q(triangle_setup$out$short0_q),
        .out$short0_rho(triangle_setup$out$short0_rho),
        .out$short0_d(triangle_setup$out$short0_d),
        .out$short0_at_z(triangle_setup$out$short0_at_z),
        .out$short0_at_c0(triangle_setup$out$short0_at_c0),
        .out$short0_at_c1(triangle_setup$out$short0_at_c1),
        .out$short0_at_c2(triangle_setup$out$short0_at_c2),
        .out$short0_inc0_z(triangle_setup$out$short0_inc0_z),
        .out$short0_inc0_c0(triangle_setup$out$short0_inc0_c0),
        .out$short0_inc0_c1(triangle_setup$out$short0_inc0_c1),
        .out$short0_inc0_c2(triangle_setup$out$short0_inc0_c2),
        .out$short0_inc1_z(triangle_setup$out$short0_inc1_z),
        .out$short0_inc1_c0(triangle_setup$out$short0_inc1_c0),
        .out$short0_inc1_c1(triangle_setup$out$short0_inc1_c1),
        .out$short0_inc1_c2(triangle_setup$out$short0_inc1_c2),
        .out$short1_j(triangle_setup$out$short1_j),
        .out$short1_count(triangle_setup$out$short1_count),
        .out$short1_x(triangle_setup$out$short1_x),
        .out$short1_r(triangle_setup$out$short1_r),
        .out$short1_q(triangle_setup$out$short1_q),
        .out$short1_rho(triangle_setup$out$short1_rho),
        .out$short1_d(triangle_setup$out$short1_d),
        .out$short1_at_z(triangle_setup$out$short1_at_z),
        .out$short1_at_c0(triangle_setup$out$short1_at_c0),
        .out$short1_at_c1(triangle_setup$out$short1_at_c1),
        .out$short1_at_c2(triangle_setup$out$short1_at_c2),
        .out$short1_inc0_z(triangle_setup$out$short1_inc0_z),
        .out$short1_inc0_c0(triangle_setup$out$short1_inc0_c0),
        .out$short1_inc0_c1(triangle_setup$out$short1_inc0_c1),
        .out$short1_inc0_c2(triangle_setup$out$short1_inc0_c2),
        .out$short1_inc1_z(triangle_setup$out$short1_inc1_z),
        .out$short1_inc1_c0(triangle_setup$out$short1_inc1_c0),
        .out$short1_inc1_c1(triangle_setup$out$short1_inc1_c1),
        .out$short1_inc1_c2(triangle_setup$out$short1_inc1_c2),
        .out$ddx_z(triangle_setup$out$ddx_z),
        .out$ddx_c0(triangle_setup$out$ddx_c0),
        .out$ddx_c1(triangle_setup$out$ddx_c1),
        .out$ddx_c2(triangle_setup$out$ddx_c2),
        .recip_mant(triangle_setup$recip_mant),
        .recip_exp(triangle_setup$recip_exp),
        .idle(triangle_setup$idle),
        .out_free_next(triangle_setup$out_free_next),
        .out_hold(triangle_setup$out_hold)
    );
    raster_top$fragments$core$edge_walk edge_walk(
        .clock(edge_walk$clock),
        .height(edge_walk$height),
        .inp$valid(edge_walk$inp$valid),
        .inp$ready(edge_walk$inp$ready),
        .inp$walk(edge_walk$inp$walk),
        .inp$maj_left(edge_walk$inp$maj_left),
        .inp$maj_j(edge_walk$inp$maj_j),
        .inp$maj_count(edge_walk$inp$maj_count),
        .inp$maj_x(edge_walk$inp$maj_x),
        .inp$maj_r(edge_walk$inp$maj_r),
        .inp$maj_q(edge_walk$inp$maj_q),
        .inp$maj_rho(edge_walk$inp$maj_rho),
        .inp$maj_d(edge_walk$inp$maj_d),
        .inp$maj_at_z(edge_walk$inp$maj_at_z),
        .inp$maj_at_c0(edge_walk$inp$maj_at_c0),
        .inp$maj_at_c1(edge_walk$inp$maj_at_c1),
        .inp$maj_at_c2(edge_walk$inp$maj_at_c2),
        .inp$maj_inc0_z(edge_walk$inp$maj_inc0_z),
        .inp$maj_inc0_c0(edge_walk$inp$maj_inc0_c0),
        .inp$maj_inc0_c1(edge_walk$inp$maj_inc0_c1),
        .inp$maj_inc0_c2(edge_walk$inp$maj_inc0_c2),
        .inp$maj_inc1_z(edge_walk$inp$maj_inc1_z),
        .inp$maj_inc1_c0(edge_walk$inp$maj_inc1_c0),
        .inp$maj_inc1_c1(edge_walk$inp$maj_inc1_c1),
        .inp$maj_inc1_c2(edge_walk$inp$maj_inc1_c2),
        .inp$short0_j(edge_walk$inp$short0_j),
        .inp$short0_count(edge_walk$inp$short0_count),
        .inp$short0_x(edge_walk$inp$short0_x),
        .inp$short0_r(edge_walk$inp$short0_r),
        .inp$short0_q(edge_walk$inp$short0_q),
        .inp$short0_rho(edge_walk$inp$short0_rho),
        .inp$short0_d(edge_walk$inp$short0_d),
        .inp$short0_at_z(edge_walk$inp$short0_at_z),
        .inp$short0_at_c0(edge_walk$inp$short0_at_c0),
        .inp$short0_at_c1(edge_walk$inp$short0_at_c1),
        .inp$short0_at_c2(edge_walk$inp$short0_at_c2),
        .inp$short0_inc0_z(edge_walk$inp$short0_inc0_z),
        .inp$short0_inc0_c0(edge_walk$inp$short0_inc0_c0),
        .inp$short0_inc0_c1(edge_walk$inp$short0_inc0_c1),
        .inp$short0_inc0_c2(edge_walk$inp$short0_inc0_c2),
        .inp$short0_inc1_z(edge_walk$inp$short0_inc1_z),
        .inp$short0_inc1_c0(edge_walk$inp$short0_inc1_c0),
        .inp$short0_inc1_c1(edge_walk$inp$short0_inc1_c1),
        .inp$short0_inc1_c2(edge_walk$inp$short0_inc1_c2),
        .inp$short1_j(edge_walk$inp$short1_j),
        .inp$short1_count(edge_walk$inp$short1_count),
        .inp$short1_x(edge_walk$inp$short1_x),
        .inp$short1_r(edge_walk$inp$short1_r),
        .inp$short1_q(edge_walk$inp$short1_q),
        .inp$short1_rho(edge_walk$inp$short1_rho),
        .inp$short1_d(edge_walk$inp$short1_d),
        .inp$short1_at_z(edge_walk$inp$short1_at_z),
        .inp$short1_at_c0(edge_walk$inp$short1_at_c0),
        .inp$short1_at_c1(edge_walk$inp$short1_at_c1),
        .inp$short1_at_c2(edge_walk$inp$short1_at_c2),
        .inp$short1_inc0_z(edge_walk$inp$short1_inc0_z),
        .inp$short1_inc0_c0(edge_walk$inp$short1_inc0_c0),
        .inp$short1_inc0_c1(edge_walk$inp$short1_inc0_c1),
        .inp$short1_inc0_c2(edge_walk$inp$short1_inc0_c2),
        .inp$short1_inc1_z(edge_walk$inp$short1_inc1_z),
        .inp$short1_inc1_c0(edge_walk$inp$short1_inc1_c0),
        .inp$short1_inc1_c1(edge_walk$inp$short1_inc1_c1),
        .inp$short1_inc1_c2(edge_walk$inp$short1_inc1_c2),
        .inp$ddx_z(edge_walk$inp$ddx_z),
        .inp$ddx_c0(edge_walk$inp$ddx_c0),
        .inp$ddx_c1(edge_walk$inp$ddx_c1),
        .inp$ddx_c2(edge_walk$inp$ddx_c2),
        .out$valid(edge_walk$out$valid),
        .out$ready(edge_walk$out$ready),
        .out$y(edge_walk$out$y),
        .out$xl(edge_walk$out$xl),
        .out$xr(edge_walk$out$xr),
        .out$left_z(edge_walk$out$left_z),
        .out$left_c0(edge_walk$out$left_c0),
        .out$left_c1(edge_walk$out$left_c1),
        .out$left_c2(edge_walk$out$left_c2),
        .out$right_z(edge_walk$out$right_z),
        .out$right_c0(edge_walk$out$right_c0),
        .out$right_c1(edge_walk$out$right_c1),
        .out$right_c2(edge_walk$out$right_c2),
        .out$ddx_z(edge_walk$out$ddx_z),
        .out$ddx_c0(edge_walk$out$ddx_c0),
        .out$ddx_c1(edge_walk$out$ddx_c1),
        .out$ddx_c2(edge_walk$out$ddx_c2),
        .hold(edge_walk$hold),
        .idle(edge_walk$idle),
        .free_next(edge_walk$free_next)
    );
    raster_top$fragments$core$fifo fifo(
        .clock(fifo$clock),
        .inp$valid(fifo$inp$valid),
        .inp$ready(fifo$inp$ready),
        .inp$y(fifo$inp$y),
        .inp$xl(fifo$inp$xl),
        .inp$xr(fifo$inp$xr),
        .inp$left_z(fifo$inp$left_z),
        .inp$left_c0(fifo$inp$left_c0),
        .inp$left_c1(fifo$inp$left_c1),
        .inp$left_c2(fifo$inp$left_c2),
        .inp$right_z(fifo$inp$right_z),
        .inp$right_c0(fifo$inp$right_c0),
        .inp$right_c1(fifo$inp$right_c1),
        .inp$right_c2(fifo$inp$right_c2),
        .inp$ddx_z(fifo$inp$ddx_z),
        .inp$ddx_c0(fifo$inp$ddx_c0),
        .inp$ddx_c1(fifo$inp$ddx_c1),
        .inp$ddx_c2(fifo$inp$ddx_c2),
        .out$valid(fifo$out$valid),
        .out$ready(fifo$out$ready),
        .out$y(fifo$out$y),
        .out$xl(fifo$out$xl),
        .out$xr(fifo$out$xr),
        .out$left_z(fifo$out$left_z),
        .out$left_c0(fifo$out$left_c0),
        .out$left_c1(fifo$out$left_c1),
        .out$left_c2(fifo$out$left_c2),
        .out$right_z(fifo$out$right_z),
        .out$right_c0(fifo$out$right_c0),
        .out$right_c1(fifo$out$right_c1),
        .out$right_c2(fifo$out$right_c2),
        .out$ddx_z(fifo$out$ddx_z),
        .out$ddx_c0(fifo$out$ddx_c0),
        .out$ddx_c1(fifo$out$ddx_c1),
        .out$ddx_c2(fifo$out$ddx_c2),
        .empty(fifo$empty)
    );
    raster_top$fragments$core$span span(
        .clock(span$clock),
        .width(span$width),
        .inp$valid(span$inp$valid),
        .inp$ready(span$inp$ready),
        .inp$y(span$inp$y),
        .inp$xl(span$inp$xl),
        .inp$xr(span$inp$xr),
        .inp$left_z(span$inp$left_z),
        .inp$left_c0(span$inp$left_c0),
        .inp$left_c1(span$inp$left_c1),
        .inp$left_c2(span$inp$left_c2),
        .inp$right_z(span$inp$right_z),
        .inp$right_c0(span$inp$right_c0),
        .inp$right_c1(span$inp$right_c1),
        .inp$right_c2(span$inp$right_c2),
        .inp$ddx_z(span$inp$ddx_z),
        .inp$ddx_c0(span$inp$ddx_c0),
        .inp$ddx_c1(span$inp$ddx_c1),
        .inp$ddx_c2(span$inp$ddx_c2),
        .out$valid(out$valid),
        .out$ready(out$ready),
        .out$x(out$x),
        .out$y(out$y),
        .out$z(out$z),
        .out$rgb0(out$rgb0),
        .out$rgb1(out$rgb1),
        .out$rgb2(out$rgb2),
        .idle(span$idle)
    );
    raster_top$fragments$core$last_in last_in(
        .d(last_in$d),
        .q(last_in$q),
        .clock(last_in$clock)
    );
    
    // Update code
    always @(*) begin
        last_in$clock = clock;
        last_in$d = last_in$q;
        triangle_setup$clock = clock;
        edge_walk$clock = clock;
        fifo$clock = clock;
        span$clock = clock;
        if (inp$valid & inp$ready) begin
            last_in$d = inp_last;
        end
        edge_walk$height = height;
        edge_walk$hold = hold;
        triangle_setup$out_free_next = edge_walk$free_next;
        triangle_setup$out_hold = hold;
        recip_mant = triangle_setup$recip_mant;
        recip_exp = triangle_setup$recip_exp;
        span$width = width;
        handed = triangle_setup$out$valid & edge_walk$inp$ready;
        walk_idle = edge_walk$idle & fifo$empty & span$idle;
        idle = triangle_setup$idle & walk_idle;
        done = last_in$q & idle;
    end
    
    always @(*) edge_walk$inp$valid = triangle_setup$out$valid;
    always @(*) triangle_setup$out$ready = edge_walk$inp$ready;
    always @(*) edge_walk$inp$walk = triangle_setup$out$walk;
    always @(*) edge_walk$inp$maj_left = triangle_setup$out$maj_left;
    always @(*) edge_walk$inp$maj_j = triangle_setup$out$maj_j;
    always @(*) edge_walk$inp$maj_count = triangle_setup$out$maj_count;
    always @(*) edge_walk$inp$maj_x = triangle_setup$out$maj_x;
    always @(*) edge_walk$inp$maj_r = triangle_setup$out$maj_r;
    always @(*) edge_walk$inp$maj_q = triangle_setup$out$maj_q;
    always @(*) edge_walk$inp$maj_rho = triangle_setup$out$maj_rho;
    always @(*) edge_walk$inp$maj_d = triangle_setup$out$maj_d;
    always @(*) edge_walk$inp$maj_at_z = triangle_setup$out$maj_at_z;
    always @(*) edge_walk$inp$maj_at_c0 = triangle_setup$out$maj_at_c0;
    always @(*) edge_walk$inp$maj_at_c1 = triangle_setup$out$maj_at_c1;
    always @(*) edge_walk$inp$maj_at_c2 = triangle_setup$out$maj_at_c2;
    always @(*) edge_walk$inp$maj_inc0_z = triangle_setup$out$maj_inc0_z;
    always @(*) edge_walk$inp$maj_inc0_c0 = triangle_setup$out$maj_inc0_c0;
    always @(*) edge_walk$inp$maj_inc0_c1 = triangle_setup$out$maj_inc0_c1;
    always @(*) edge_walk$inp$maj_inc0_c2 = triangle_setup$out$maj_inc0_c2;
    always @(*) edge_walk$inp$maj_inc1_z = triangle_setup$out$maj_inc1_z;
    always @(*) edge_walk$inp$maj_inc1_c0 = triangle_setup$out$maj_inc1_c0;
    always @(*) edge_walk$inp$maj_inc1_c1 = triangle_setup$out$maj_inc1_c1;
    always @(*) edge_walk$inp$maj_inc1_c2 = triangle_setup$out$maj_inc1_c2;
    always @(*) edge_walk$inp$short0_j = triangle_setup$out$short0_j;
    always @(*) edge_walk$inp$short0_count = triangle_setup$out$short0_count;
    always @(*) edge_walk$inp$short0_x = triangle_setup$out$short0_x;
    always @(*) edge_walk$inp$short0_r = triangle_setup$out$short0_r;
    always @(*) edge_walk$inp$short0_q = triangle_setup$out$short0_q;
    always @(*) edge_walk$inp$short0_rho = triangle_setup$out$short0_rho;
    always @(*) edge_walk$inp$short0_d = triangle_setup$out$short0_d;
    always @(*) edge_walk$inp$short0_at_z = triangle_setup$out$short0_at_z;
    always @(*) edge_walk$inp$short0_at_c0 = triangle_setup$out$short0_at_c0;
    always @(*) edge_walk$inp$short0_at_c1 = triangle_setup$out$short0_at_c1;
    always @(*) edge_walk$inp$short0_at_c2 = triangle_setup$out$short0_at_c2;
    always @(*) edge_walk$inp$short0_inc0_z = triangle_setup$out$short0_inc0_z;
    always @(*) edge_walk$inp$short0_inc0_c0 = triangle_setup$out$short0_inc0_c0;
    always @(*) edge_walk$inp$short0_inc0_c1 = triangle_setup$out$short0_inc0_c1;
    always @(*) edge_walk$inp$short0_inc0_c2 = triangle_setup$out$short0_inc0_c2;
    always @(*) edge_walk$inp$short0_inc1_z = triangle_setup$out$short0_inc1_z;
    always @(*) edge_walk$inp$short0_inc1_c0 = triangle_setup$out$short0_inc1_c0;
    always @(*) edge_walk$inp$short0_inc1_c1 = triangle_setup$out$short0_inc1_c1;
    always @(*) edge_walk$inp$short0_inc1_c2 = triangle_setup$out$short0_inc1_c2;
    always @(*) edge_walk$inp$short1_j = triangle_setup$out$short1_j;
    always @(*) edge_walk$inp$short1_count = triangle_setup$out$short1_count;
    always @(*) edge_walk$inp$short1_x = triangle_setup$out$short1_x;
    always @(*) edge_walk$inp$short1_r = triangle_setup$out$short1_r;
    always @(*) edge_walk$inp$short1_q = triangle_setup$out$short1_q;
    always @(*) edge_walk$inp$short1_rho = triangle_setup$out$short1_rho;
    always @(*) edge_walk$inp$short1_d = triangle_setup$out$short1_d;
    always @(*) edge_walk$inp$short1_at_z = triangle_setup$out$short1_at_z;
    always @(*) edge_walk$inp$short1_at_c0 = triangle_setup$out$short1_at_c0;
    always @(*) edge_walk$inp$short1_at_c1 = triangle_setup$out$short1_at_c1;
    always @(*) edge_walk$inp$short1_at_c2 = triangle_setup$out$short1_at_c2;
    always @(*) edge_walk$inp$short1_inc0_z = triangle_setup$out$short1_inc0_z;
    always @(*) edge_walk$inp$short1_inc0_c0 = triangle_setup$out$short1_inc0_c0;
    always @(*) edge_walk$inp$short1_inc0_c1 = triangle_setup$out$short1_inc0_c1;
    always @(*) edge_walk$inp$short1_inc0_c2 = triangle_setup$out$short1_inc0_c2;
    always @(*) edge_walk$inp$short1_inc1_z = triangle_setup$out$short1_inc1_z;
    always @(*) edge_walk$inp$short1_inc1_c0 = triangle_setup$out$short1_inc1_c0;
    always @(*) edge_walk$inp$short1_inc1_c1 = triangle_setup$out$short1_inc1_c1;
    always @(*) edge_walk$inp$short1_inc1_c2 = triangle_setup$out$short1_inc1_c2;
    always @(*) edge_walk$inp$ddx_z = triangle_setup$out$ddx_z;
    always @(*) edge_walk$inp$ddx_c0 = triangle_setup$out$ddx_c0;
    always @(*) edge_walk$inp$ddx_c1 = triangle_setup$out$ddx_c1;
    always @(*) edge_walk$inp$ddx_c2 = triangle_setup$out$ddx_c2;
    always @(*) fifo$inp$valid = edge_walk$out$valid;
    always @(*) edge_walk$out$ready = fifo$inp$ready;
    always @(*) fifo$inp$y = edge_walk$out$y;
    always @(*) fifo$inp$xl = edge_walk$out$xl;
    always @(*) fifo$inp$xr = edge_walk$out$xr;
    always @(*) fifo$inp$left_z = edge_walk$out$left_z;
    always @(*) fifo$inp$left_c0 = edge_walk$out$left_c0;
    always @(*) fifo$inp$left_c1 = edge_walk$out$left_c1;
    always @(*) fifo$inp$left_c2 = edge_walk$out$left_c2;
    always @(*) fifo$inp$right_z = edge_walk$out$right_z;
    always @(*) fifo$inp$right_c0 = edge_walk$out$right_c0;
    always @(*) fifo$inp$right_c1 = edge_walk$out$right_c1;
    always @(*) fifo$inp$right_c2 = edge_walk$out$right_c2;
    always @(*) fifo$inp$ddx_z = edge_walk$out$ddx_z;
    always @(*) fifo$inp$ddx_c0 = edge_walk$out$ddx_c0;
    always @(*) fifo$inp$ddx_c1 = edge_walk$out$ddx_c1;
    always @(*) fifo$inp$ddx_c2 = edge_walk$out$ddx_c2;
    always @(*) span$inp$valid = fifo$out$valid;
    always @(*) fifo$out$ready = span$inp$ready;
    always @(*) span$inp$y = fifo$out$y;
    always @(*) span$inp$xl = fifo$out$xl;
    always @(*) span$inp$xr = fifo$out$xr;
    always @(*) span$inp$left_z = fifo$out$left_z;
    always @(*) span$inp$left_c0 = fifo$out$left_c0;
    always @(*) span$inp$left_c1 = fifo$out$left_c1;
    always @(*) span$inp$left_c2 = fifo$out$left_c2;
    always @(*) span$inp$right_z = fifo$out$right_z;
    always @(*) span$inp$right_c0 = fifo$out$right_c0;
    always @(*) span$inp$right_c1 = fifo$out$right_c1;
    always @(*) span$inp$right_c2 = fifo$out$right_c2;
    always @(*) span$inp$ddx_z = fifo$out$ddx_z;
    always @(*) span$inp$ddx_c0 = fifo$out$ddx_c0;
    always @(*) span$inp$ddx_c1 = fifo$out$ddx_c1;
    always @(*) span$inp$ddx_c2 = fifo$out$ddx_c2;
endmodule // raster_top$fragments$core


module raster_top$fragments$core$edge_walk(clock,height,inp$valid,inp$ready,inp$walk,inp$maj_left,inp$maj_j,inp$maj_count,inp$maj_x,inp$maj_r,inp$maj_q,inp$maj_rho,inp$maj_d,inp$maj_at_z,inp$maj_at_c0,inp$maj_at_c1,inp$maj_at_c2,inp$maj_inc0_z,inp$maj_inc0_c0,inp$maj_inc0_c1,inp$maj_inc0_c2,inp$maj_inc1_z,inp$maj_inc1_c0,inp$maj_inc1_c1,inp$maj_inc1_c2,inp$short0_j,inp$short0_count,inp$short0_x,inp$short0_r,inp$short0_q,inp$short0_rho,inp$short0_d,inp$short0_at_z,inp$short0_at_c0,inp$short0_at_c1,inp$short0_at_c2,inp$short0_inc0_z,inp$short0_inc0_c0,inp$short0_inc0_c1,inp$short0_inc0_c2,inp$short0_inc1_z,inp$short0_inc1_c0,inp$short0_inc1_c1,inp$short0_inc1_c2,inp$short1_j,inp$short1_count,inp$short1_x,inp$short1_r,inp$short1_q,inp$short1_rho,inp$short1_d,inp$short1_at_z,inp$short1_at_c0,inp$short1_at_c1,inp$short1_at_c2,inp$short1_inc0_z,inp$short1_inc0_c0,inp$short1_inc0_c1,inp$short1_inc0_c2,inp$short1_inc1_z,inp$short1_inc1_c0,inp$short1_inc1_c1,inp$short1_inc1_c2,inp$ddx_z,inp$ddx_c0,inp$ddx_c1,inp$ddx_c2,out$valid,out$ready,out$y,out$xl,out$xr,out$left_z,out$left_c0,out$left_c1,out$left_c2,out$right_z,out$right_c0,out$right_c1,out$right_c2,out$ddx_z,out$ddx_c0,out$ddx_c1,out$ddx_c2,hold,idle,free_next);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] height;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  inp$walk;
    input wire  inp$maj_left;
    input wire  [12:0] inp$maj_j;
    input wire  [12:0] inp$maj_count;
    input wire  [12:0] inp$maj_x;
    input wire  [20:0] inp$maj_r;
    input wire  [16:0] inp$maj_q;
    input wire  [20:0] inp$maj_rho;
    input wire  [20:0] inp$maj_d;
    input wire  [35:0] inp$maj_at_z;
    input wire  [31:0] inp$maj_at_c0;
    input wire  [31:0] inp$maj_at_c1;
    input wire  [31:0] inp$maj_at_c2;
    input wire  [39:0] inp$maj_inc0_z;
    input wire  [35:0] inp$maj_inc0_c0;
    input wire  [35:0] inp$maj_inc0_c1;
    input wire  [35:0] inp$maj_inc0_c2;
    input wire  [39:0] inp$maj_inc1_z;
    input wire  [35:0] inp$maj_inc1_c0;
    input wire  [35:0] inp$maj_inc1_c1;
    input wire  [35:0] inp$maj_inc1_c2;
    input wire  [12:0] inp$short0_j;
    input wire  [12:0] inp$short0_count;
    input wire  [12:0] inp$short0_x;
    input wire  [20:0] inp$short0_r;
    input wire  [16:0] inp$short0_q;
    input wire  [20:0] inp$short0_rho;
    input wire  [20:0] inp$short0_d;
    input wire  [35:0] inp$short0_at_z;
    input wire  [31:0] inp$short0_at_c0;
    input wire  [31:0] inp$short0_at_c1;
    input wire  [31:0] inp$short0_at_c2;
    input wire  [39:0] inp$short0_inc0_z;
    input wire  [35:0] inp$short0_inc0_c0;
    input wire  [35:0] inp$short0_inc0_c1;
    input wire  [35:0] inp$short0_inc0_c2;
    input wire  [39:0] inp$short0_inc1_z;
    input wire  [35:0] inp$short0_inc1_c0;
    input wire  [35:0] inp$short0_inc1_c1;
    input wire  [35:0] inp$short0_inc1_c2;
    input wire  [12:0] inp$short1_j;
    input wire  [12:0] inp$short1_count;
    input wire  [12:0] inp$short1_x;
    input wire  [20:0] inp$short1_r;
    input wire  [16:0] inp$short1_q;
    input wire  [20:0] inp$short1_rho;
    input wire  [20:0] inp$short1_d;
    input wire  [35:0] inp$short1_at_z;
    input wire  [31:0] inp$short1_at_c0;
    input wire  [31:0] inp$short1_at_c1;
    input wire  [31:0] inp$short1_at_c2;
    input wire  [39:0] inp$short1_inc0_z;
    input wire  [35:0] inp$short1_inc0_c0;
    input wire  [35:0] inp$short1_inc0_c1;
    input wire  [35:0] inp$short1_inc0_c2;
    input wire  [39:0] inp$short1_inc1_z;
    input wire  [35:0] inp$short1_inc1_c0;
    input wire  [35:0] inp$short1_inc1_c1;
    input wire  [35:0] inp$short1_inc1_c2;
    input wire  [39:0] inp$ddx_z;
    input wire  [35:0] inp$ddx_c0;
    input wire  [35:0] inp$ddx_c1;
    input wire  [35:0] inp$ddx_c2;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [9:0] out$y;
    output reg  [12:0] out$xl;
    output reg  [12:0] out$xr;
    output reg  [35:0] out$left_z;
    output reg  [31:0] out$left_c0;
    output reg  [31:0] out$left_c1;
    output reg  [31:0] out$left_c2;
    output reg  [35:0] out$right_z;
    output reg  [31:0] out$right_c0;
    output reg  [31:0] out$right_c1;
    output reg  [31:0] out$right_c2;
    output reg  [39:0] out$ddx_z;
    output reg  [35:0] out$ddx_c0;
    output reg  [35:0] out$ddx_c1;
    output reg  [35:0] out$ddx_c2;
    input wire  hold;
    output reg  idle;
    output reg  free_next;
    
    // Stub signals
    wire  clip_y$on;
    reg  maj$clock;
    reg  maj$load;
    reg  maj$step;
    reg  maj$up;
    reg  [12:0] maj$ld_x;
    reg  [12:0] maj$ld_q;
    reg  [21:0] maj$ld_t;
    reg  [21:0] maj$ld_a;
    reg  [21:0] maj$ld_b;
    reg  [35:0] maj$ld_at_z;
    reg  [31:0] maj$ld_at_c0;
    reg  [31:0] maj$ld_at_c1;
    reg  [31:0] maj$ld_at_c2;
    reg  [35:0] maj$ld_inc0_z;
    reg  [31:0] maj$ld_inc0_c0;
    reg  [31:0] maj$ld_inc0_c1;
    reg  [31:0] maj$ld_inc0_c2;
    reg  [35:0] maj$ld_inc1_z;
    reg  [31:0] maj$ld_inc1_c0;
    reg  [31:0] maj$ld_inc1_c1;
    reg  [31:0] maj$ld_inc1_c2;
    wire  [12:0] maj$x;
    wire  [35:0] maj$at_z;
    wire  [31:0] maj$at_c0;
    wire  [31:0] maj$at_c1;
    wire  [31:0] maj$at_c2;
    reg  cur$clock;
    reg  cur$load;
    reg  cur$step;
    reg  cur$up;
    reg  [12:0] cur$ld_x;
    reg  [12:0] cur$ld_q;
    reg  [21:0] cur$ld_t;
    reg  [21:0] cur$ld_a;
    reg  [21:0] cur$ld_b;
    reg  [35:0] cur$ld_at_z;
    reg  [31:0] cur$ld_at_c0;
    reg  [31:0] cur$ld_at_c1;
    reg  [31:0] cur$ld_at_c2;
    reg  [35:0] cur$ld_inc0_z;
    reg  [31:0] cur$ld_inc0_c0;
    reg  [31:0] cur$ld_inc0_c1;
    reg  [31:0] cur$ld_inc0_c2;
    reg  [35:0] cur$ld_inc1_z;
    reg  [31:0] cur$ld_inc1_c0;
    reg  [31:0] cur$ld_inc1_c1;
    reg  [31:0] cur$ld_inc1_c2;
    wire  [12:0] cur$x;
    wire  [35:0] cur$at_z;
    wire  [31:0] cur$at_c0;
    wire  [31:0] cur$at_c1;
    wire  [31:0] cur$at_c2;
    reg  start_maj$up;
    reg  [20:0] start_maj$r;
    reg  [20:0] start_maj$rho;
    reg  [20:0] start_maj$d;
    wire  [21:0] start_maj$t;
    wire  [21:0] start_maj$a;
    wire  [21:0] start_maj$b;
    reg  start_s0$up;
    reg  [20:0] start_s0$r;
    reg  [20:0] start_s0$rho;
    reg  [20:0] start_s0$d;
    wire  [21:0] start_s0$t;
    wire  [21:0] start_s0$a;
    wire  [21:0] start_s0$b;
    reg  start_s1$up;
    reg  [20:0] start_s1$r;
    reg  [20:0] start_s1$rho;
    reg  [20:0] start_s1$d;
    wire  [21:0] start_s1$t;
    wire  [21:0] start_s1$a;
    wire  [21:0] start_s1$b;
    reg  busy$d;
    wire  busy$q;
    reg  busy$clock;
    reg  walking$d;
    wire  walking$q;
    reg  walking$clock;
    reg  up$d;
    wire  up$q;
    reg  up$clock;
    reg  maj_left$d;
    wire  maj_left$q;
    reg  maj_left$clock;
    reg  [12:0] j$d;
    wire  [12:0] j$q;
    reg  j$clock;
    reg  [12:0] rem$d;
    wire  [12:0] rem$q;
    reg  rem$clock;
    reg  [12:0] crow$d;
    wire  [12:0] crow$q;
    reg  crow$clock;
    reg  [12:0] crem$d;
    wire  [12:0] crem$q;
    reg  crem$clock;
    reg  last_r$d;
    wire  last_r$q;
    reg  last_r$clock;
    reg  sw_r$d;
    wire  sw_r$q;
    reg  sw_r$clock;
    reg  [39:0] ddx_z$d;
    wire  [39:0] ddx_z$q;
    reg  ddx_z$clock;
    reg  [35:0] ddx_c0$d;
    wire  [35:0] ddx_c0$q;
    reg  ddx_c0$clock;
    reg  [35:0] ddx_c1$d;
    wire  [35:0] ddx_c1$q;
    reg  ddx_c1$clock;
    reg  [35:0] ddx_c2$d;
    wire  [35:0] ddx_c2$q;
    reg  ddx_c2$clock;
    reg  [12:0] pend_x$d;
    wire  [12:0] pend_x$q;
    reg  pend_x$clock;
    reg  [12:0] pend_q$d;
    wire  [12:0] pend_q$q;
    reg  pend_q$clock;
    reg  [21:0] pend_t$d;
    wire  [21:0] pend_t$q;
    reg  pend_t$clock;
    reg  [21:0] pend_a$d;
    wire  [21:0] pend_a$q;
    reg  pend_a$clock;
    reg  [21:0] pend_b$d;
    wire  [21:0] pend_b$q;
    reg  pend_b$clock;
    reg  [35:0] pend_at_z$d;
    wire  [35:0] pend_at_z$q;
    reg  pend_at_z$clock;
    reg  [31:0] pend_at_c0$d;
    wire  [31:0] pend_at_c0$q;
    reg  pend_at_c0$clock;
    reg  [31:0] pend_at_c1$d;
    wire  [31:0] pend_at_c1$q;
    reg  pend_at_c1$clock;
    reg  [31:0] pend_at_c2$d;
    wire  [31:0] pend_at_c2$q;
    reg  pend_at_c2$clock;
    reg  [35:0] pend_inc0_z$d;
    wire  [35:0] pend_inc0_z$q;
    reg  pend_inc0_z$clock;
    reg  [31:0] pend_inc0_c0$d;
    wire  [31:0] pend_inc0_c0$q;
    reg  pend_inc0_c0$clock;
    reg  [31:0] pend_inc0_c1$d;
    wire  [31:0] pend_inc0_c1$q;
    reg  pend_inc0_c1$clock;
    reg  [31:0] pend_inc0_c2$d;
    wire  [31:0] pend_inc0_c2$q;
    reg  pend_inc0_c2$clock;
    reg  [35:0] pend_inc1_z$d;
    wire  [35:0] pend_inc1_z$q;
    reg  pend_inc1_z$clock;
    reg  [31:0] pend_inc1_c0$d;
    wire  [31:0] pend_inc1_c0$q;
    reg  pend_inc1_c0$clock;
    reg  [31:0] pend_inc1_c1$d;
    wire  [31:0] pend_inc1_c1$q;
    reg  pend_inc1_c1$clock;
    reg  [31:0] pend_inc1_c2$d;
    wire  [31:0] pend_inc1_c2$q;
    reg  pend_inc1_c2$clock;
    reg  o_valid$d;
    wire  o_valid$q;
    reg  o_valid$clock;
    reg  [9:0] o_y$d;
    wire  [9:0] o_y$q;
    reg  o_y$clock;
    reg  [12:0] o_xl$d;
    wire  [12:0] o_xl$q;
    reg  o_xl$clock;
    reg  [12:0] o_xr$d;
    wire  [12:0] o_xr$q;
    reg  o_xr$clock;
    reg  [35:0] o_left_z$d;
    wire  [35:0] o_left_z$q;
    reg  o_left_z$clock;
    reg  [31:0] o_left_c0$d;
    wire  [31:0] o_left_c0$q;
    reg  o_left_c0$clock;
    reg  [31:0] o_left_c1$d;
    wire  [31:0] o_left_c1$q;
    reg  o_left_c1$clock;
    reg  [31:0] o_left_c2$d;
    wire  [31:0] o_left_c2$q;
    reg  o_left_c2$clock;
    reg  [35:0] o_right_z$d;
    wire  [35:0] o_right_z$q;
    reg  o_right_z$clock;
    reg  [31:0] o_right_c0$d;
    wire  [31:0] o_right_c0$q;
    reg  o_right_c0$clock;
    reg  [31:0] o_right_c1$d;
    wire  [31:0] o_right_c1$q;
    reg  o_right_c1$clock;
    reg  [31:0] o_right_c2$d;
    wire  [31:0] o_right_c2$q;
    reg  o_right_c2$clock;
    reg  [12:0] j_sign$x;
    wire  j_sign$neg;
    reg  [12:0] sides$a;
    reg  [12:0] sides$b;
    wire  sides$lt;
    reg  [12:0] in_j_sign$x;
    wire  in_j_sign$neg;
    
    // Local signals
    reg  accept;
    reg  in_up;
    reg  in_no_rows;
    reg  [12:0] in_crow;
    reg  in_last;
    reg  in_short0_none;
    reg  [12:0] height_j;
    reg  free;
    reg  emit;
    reg  step;
    reg  valid;
    reg  [12:0] j_next;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$clip_y clip_y(
        .on(clip_y$on)
    );
    raster_top$fragments$core$edge_walk$maj maj(
        .clock(maj$clock),
        .load(maj$load),
        .step(maj$step),
        .up(maj$up),
        .ld_x(maj$ld_x),
        .ld_q(maj$ld_q),
        .ld_t(maj$ld_t),
        .ld_a(maj$ld_a),
        .ld_b(maj$ld_b),
        .ld_at_z(maj$ld_at_z),
        .ld_at_c0(maj$ld_at_c0),
        .ld_at_c1(maj$ld_at_c1),
        .ld_at_c2(maj$ld_at_c2),
        .ld_inc0_z(maj$ld_inc0_z),
        .ld_inc0_c0(maj$ld_inc0_c0),
        .ld_inc0_c1(maj$ld_inc0_c1),
        .ld_inc0_c2(maj$ld_inc0_c2),
        .ld_inc1_z(maj$ld_inc1_z),
        .ld_inc1_c0(maj$ld_inc1_c0),
        .ld_inc1_c1(maj$ld_inc1_c1),
        .ld_inc1_c2(maj$ld_inc1_c2),
        .x(maj$x),
        .at_z(maj$at_z),
        .at_c0(maj$at_c0),
        .at_c1(maj$at_c1),
        .at_c2(maj$at_c2)
    );
    raster_top$fragments$core$edge_walk$cur cur(
        .clock(cur$clock),
        .load(cur$load),
        .step(cur$step),
        .up(cur$up),
        .ld_x(cur$ld_x),
        .ld_q(cur$ld_q),
        .ld_t(cur$ld_t),
        .ld_a(cur$ld_a),
        .ld_b(cur$ld_b),
        .ld_at_z(cur$ld_at_z),
        .ld_at_c0(cur$ld_at_c0),
        .ld_at_c1(cur$ld_at_c1),
        .ld_at_c2(cur$ld_at_c2),
        .ld_inc0_z(cur$ld_inc0_z),
        .ld_inc0_c0(cur$ld_inc0_c0),
        .ld_inc0_c1(cur$ld_inc0_c1),
        .ld_inc0_c2(cur$ld_inc0_c2),
        .ld_inc1_z(cur$ld_inc1_z),
        .ld_inc1_c0(cur$ld_inc1_c0),
        .ld_inc1_c1(cur$ld_inc1_c1),
        .ld_inc1_c2(cur$ld_inc1_c2),
        .x(cur$x),
        .at_z(cur$at_z),
        .at_c0(cur$at_c0),
        .at_c1(cur$at_c1),
        .at_c2(cur$at_c2)
    );
    raster_top$fragments$core$edge_walk$start_maj start_maj(
        .up(start_maj$up),
        .r(start_maj$r),
        .rho(start_maj$rho),
        .d(start_maj$d),
        .t(start_maj$t),
        .a(start_maj$a),
        .b(start_maj$b)
    );
    raster_top$fragments$core$edge_walk$start_s0 start_s0(
        .up(start_s0$up),
        .r(start_s0$r),
        .rho(start_s0$rho),
        .d(start_s0$d),
        .t(start_s0$t),
        .a(start_s0$a),
        .b(start_s0$b)
    );
    raster_top$fragments$core$edge_walk$start_s1 start_s1(
        .up(start_s1$up),
        .r(start_s1$r),
        .rho(start_s1$rho),
        .d(start_s1$d),
        .t(start_s1$t),
        .a(start_s1$a),
        .b(start_s1$b)
    );
    raster_top$fragments$core$edge_walk$busy busy(
        .d(busy$d),
        .q(busy$q),
        .clock(busy$clock)
    );
    raster_top$fragments$core$edge_walk$walking walking(
        .d(walking$d),
        .q(walking$q),
        .clock(walking$clock)
    );
    raster_top$fragments$core$edge_walk$up up(
        .d(up$d),
        .q(up$q),
        .clock(up$clock)
    );
    raster_top$fragments$core$edge_walk$maj_left maj_left(
        .d(maj_left$d),
        .q(maj_left$q),
        .clock(maj_left$clock)
    );
    raster_top$fragments$core$edge_walk$j j(
        .d(j$d),
        .q(j$q),
        .clock(j$clock)
    );
    raster_top$fragments$core$edge_walk$rem rem(
        .d(rem$d),
        .q(rem$q),
        .clock(rem$clock)
    );
    raster_top$fragments$core$edge_walk$crow crow(
        .d(crow$d),
        .q(crow$q),
        .clock(crow$clock)
    );
    raster_top$fragments$core$edge_walk$crem crem(
        .d(crem$d),
        .q(crem$q),
        .clock(crem$clock)
    );
    raster_top$fragments$core$edge_walk$last_r last_r(
        .d(last_r$d),
        .q(last_r$q),
        .clock(last_r$clock)
    );
    raster_top$fragments$core$edge_walk$sw_r sw_r(
        .d(sw_r$d),
        .q(sw_r$q),
        .clock(sw_r$clock)
    );
    raster_top$fragments$core$edge_walk$ddx_z ddx_z(
        .d(ddx_z$d),
        .q(ddx_z$q),
        .clock(ddx_z$clock)
    );
    raster_top$fragments$core$edge_walk$ddx_c0 ddx_c0(
        .d(ddx_c0$d),
        .q(ddx_c0$q),
        .clock(ddx_c0$clock)
    );
    raster_top$fragments$core$edge_walk$ddx_c1 ddx_c1(
        .d(ddx_c1$d),
        .q(ddx_c1$q),
        .clock(ddx_c1$clock)
    );
    raster_top$fragments$core$edge_walk$ddx_c2 ddx_c2(
        .d(ddx_c2$d),
        .q(ddx_c2$q),
        .clock(ddx_c2$clock)
    );
    raster_top$fragments$core$edge_walk$pend_x pend_x(
        .d(pend_x$d),
        .q(pend_x$q),
        .clock(pend_x$clock)
    );
    raster_top$fragments$core$edge_walk$pend_q pend_q(
        .d(pend_q$d),
        .q(pend_q$q),
        .clock(pend_q$clock)
    );
    raster_top$fragments$core$edge_walk$pend_t pend_t(
        .d(pend_t$d),
        .q(pend_t$q),
        .clock(pend_t$clock)
    );
    raster_top$fragments$core$edge_walk$pend_a pend_a(
        .d(pend_a$d),
        .q(pend_a$q),
        .clock(pend_a$clock)
    );
    raster_top$fragments$core$edge_walk$pend_b pend_b(
        .d(pend_b$d),
        .q(pend_b$q),
        .clock(pend_b$clock)
    );
    raster_top$fragments$core$edge_walk$pend_at_z pend_at_z(
        .d(pend_at_z$d),
        .q(pend_at_z$q),
        .clock(pend_at_z$clock)
    );
    raster_top$fragments$core$edge_walk$pend_at_c0 pend_at_c0(
        .d(pend_at_c0$d),
        .q(pend_at_c0$q),
        .clock(pend_at_c0$clock)
    );
    raster_top$fragments$core$edge_walk$pend_at_c1 pend_at_c1(
        .d(pend_at_c1$d),
        .q(pend_at_c1$q),
        .clock(pend_at_c1$clock)
    );
    raster_top$fragments$core$edge_walk$pend_at_c2 pend_at_c2(
        .d(pend_at_c2$d),
        .q(pend_at_c2$q),
        .clock(pend_at_c2$clock)
    );
    raster_top$fragments$core$edge_walk$pend_inc0_z pend_inc0_z(
        .d(pend_inc0_z$d),
        .q(pend_inc0_z$q),
        .clock(pend_inc0_z$clock)
    );
    raster_top$fragments$core$edge_walk$pend_inc0_c0 pend_inc0_c0(
        .d(pend_inc0_c0$d),
        .q(pend_inc0_c0$q),
        .clock(pend_inc0_c0$clock)
    );
    raster_top$fragments$core$edge_walk$pend_inc0_c1 pend_inc0_c1(
        .d(pend_inc0_c1$d),
        .q(pend_inc0_c1$q),
        .clock(pend_inc0_c1$clock)
    );
    raster_top$fragments$core$edge_walk$pend_inc0_c2 pend_inc0_c2(
        .d(pend_inc0_c2$d),
        .q(pend_inc0_c2$q),
        .clock(pend_inc0_c2$clock)
    );
    raster_top$fragments$core$edge_walk$pend_inc1_z pend_inc1_z(
        .d(pend_inc1_z$d),
        .q(pend_inc1_z$q),
        .clock(pend_inc1_z$clock)
    );
    raster_top$fragments$core$edge_walk$pend_inc1_c0 pend_inc1_c0(
        .d(pend_inc1_c0$d),
        .q(pend_inc1_c0$q),
        .clock(pend_inc1_c0$clock)
    );
    raster_top$fragments$core$edge_walk$pend_inc1_c1 pend_inc1_c1(
        .d(pend_inc1_c1$d),
        .q(pend_inc1_c1$q),
        .clock(pend_inc1_c1$clock)
    );
    raster_top$fragments$core$edge_walk$pend_inc1_c2 pend_inc1_c2(
        .d(pend_inc1_c2$d),
        .q(pend_inc1_c2$q),
        .clock(pend_inc1_c2$clock)
    );
    raster_top$fragments$core$edge_walk$o_valid o_valid(
        .d(o_valid$d),
        .q(o_valid$q),
        .clock(o_valid$clock)
    );
    raster_top$fragments$core$edge_walk$o_y o_y(
        .d(o_y$d),
        .q(o_y$q),
        .clock(o_y$clock)
    );
    raster_top$fragments$core$edge_walk$o_xl o_xl(
        .d(o_xl$d),
        .q(o_xl$q),
        .clock(o_xl$clock)
    );
    raster_top$fragments$core$edge_walk$o_xr o_xr(
        .d(o_xr$d),
        .q(o_xr$q),
        .clock(o_xr$clock)
    );
    raster_top$fragments$core$edge_walk$o_left_z o_left_z(
        .d(o_left_z$d),
        .q(o_left_z$q),
        .clock(o_left_z$clock)
    );
    raster_top$fragments$core$edge_walk$o_left_c0 o_left_c0(
        .d(o_left_c0$d),
        .q(o_left_c0$q),
        .clock(o_left_c0$clock)
    );
    raster_top$fragments$core$edge_walk$o_left_c1 o_left_c1(
        .d(o_left_c1$d),
        .q(o_left_c1$q),
        .clock(o_left_c1$clock)
    );
    raster_top$fragments$core$edge_walk$o_left_c2 o_left_c2(
        .d(o_left_c2$d),
        .q(o_left_c2$q),
        .clock(o_left_c2$clock)
    );
    raster_top$fragments$core$edge_walk$o_right_z o_right_z(
        .d(o_right_z$d),
        .q(o_right_z$q),
        .clock(o_right_z$clock)
    );
    raster_top$fragments$core$edge_walk$o_right_c0 o_right_c0(
        .d(o_right_c0$d),
        .q(o_right_c0$q),
        .clock(o_right_c0$clock)
    );
    raster_top$fragments$core$edge_walk$o_right_c1 o_right_c1(
        .d(o_right_c1$d),
        .q(o_right_c1$q),
        .clock(o_right_c1$clock)
    );
    raster_top$fragments$core$edge_walk$o_right_c2 o_right_c2(
        .d(o_right_c2$d),
        .q(o_right_c2$q),
        .clock(o_right_c2$clock)
    );
    raster_top$fragments$core$edge_walk$j_sign j_sign(
        .x(j_sign$x),
        .neg(j_sign$neg)
    );
    raster_top$fragments$core$edge_walk$sides sides(
        .a(sides$a),
        .b(sides$b),
        .lt(sides$lt)
    );
    raster_top$fragments$core$edge_walk$in_j_sign in_j_sign(
        .x(in_j_sign$x),
        .neg(in_j_sign$neg)
    );
    
    // Update code
    always @(*) begin
        busy$clock = clock;
        walking$clock = clock;
        up$clock = clock;
        maj_left$clock = clock;
        j$clock = clock;
        rem$clock = clock;
        crow$clock = clock;
        crem$clock = clock;
        last_r$clock = clock;
        sw_r$clock = clock;
        ddx_z$clock = clock;
        ddx_c0$clock = clock;
        ddx_c1$clock = clock;
        ddx_c2$clock = clock;
        pend_x$clock = clock;
        pend_q$clock = clock;
        pend_t$clock = clock;
        pend_a$clock = clock;
        pend_b$clock = clock;
        pend_at_z$clock = clock;
        pend_at_c0$clock = clock;
        pend_at_c1$clock = clock;
        pend_at_c2$clock = clock;
        pend_inc0_z$clock = clock;
        pend_inc0_c0$clock = clock;
        pend_inc0_c1$clock = clock;
        pend_inc0_c2$clock = clock;
        pend_inc1_z$clock = clock;
        pend_inc1_c0$clock = clock;
        pend_inc1_c1$clock = clock;
        pend_inc1_c2$clock = clock;
        o_valid$clock = clock;
        o_y$clock = clock;
        o_xl$clock = clock;
        o_xr$clock = clock;
        o_left_z$clock = clock;
        o_left_c0$clock = clock;
        o_left_c1$clock = clock;
        o_left_c2$clock = clock;
        o_right_z$clock = clock;
        o_right_c0$clock = clock;
        o_right_c1$clock = clock;
        o_right_c2$clock = clock;
        busy$d = busy$q;
        walking$d = walking$q;
        up$d = up$q;
        maj_left$d = maj_left$q;
        j$d = j$q;
        rem$d = rem$q;
        crow$d = crow$q;
        crem$d = crem$q;
        last_r$d = last_r$q;
        sw_r$d = sw_r$q;
        ddx_z$d = ddx_z$q;
        ddx_c0$d = ddx_c0$q;
        ddx_c1$d = ddx_c1$q;
        ddx_c2$d = ddx_c2$q;
        pend_x$d = pend_x$q;
        pend_q$d = pend_q$q;
        pend_t$d = pend_t$q;
        pend_a$d = pend_a$q;
        pend_b$d = pend_b$q;
        pend_at_z$d = pend_at_z$q;
        pend_at_c0$d = pend_at_c0$q;
        pend_at_c1$d = pend_at_c1$q;
        pend_at_c2$d = pend_at_c2$q;
        pend_inc0_z$d = pend_inc0_z$q;
        pend_inc0_c0$d = pend_inc0_c0$q;
        pend_inc0_c1$d = pend_inc0_c1$q;
        pend_inc0_c2$d = pend_inc0_c2$q;
        pend_inc1_z$d = pend_inc1_z$q;
        pend_inc1_c0$d = pend_inc1_c0$q;
        pend_inc1_c1$d = pend_inc1_c1$q;
        pend_inc1_c2$d = pend_inc1_c2$q;
        o_valid$d = o_valid$q;
        o_y$d = o_y$q;
        o_xl$d = o_xl$q;
        o_xr$d = o_xr$q;
        o_left_z$d = o_left_z$q;
        o_left_c0$d = o_left_c0$q;
        o_left_c1$d = o_left_c1$q;
        o_left_c2$d = o_left_c2$q;
        o_right_z$d = o_right_z$q;
        o_right_c0$d = o_right_c0$q;
        o_right_c1$d = o_right_c1$q;
        o_right_c2$d = o_right_c2$q;
        maj$clock = clock;
        cur$clock = clock;
        idle = ~busy$q;
        inp$ready = ~busy$q & ~hold;
        accept = inp$valid & ~busy$q & ~hold;
        in_up = inp$walk & clip_y$on;
        height_j = ((height) & 13'h1fff);
        in_j_sign$x = inp$maj_j;
        in_no_rows = inp$maj_count == 32'h0;
        if (clip_y$on) begin
            if (in_up) begin
                if (in_j_sign$neg) begin
                    in_no_rows = 1'b1;
                end
            end
            else if (~in_j_sign$neg & (inp$maj_j >= height_j)) begin
                in_no_rows = 1'b1;
            end
        end
        in_crow = height_j + ~inp$maj_j;
        if (in_up) begin
            in_crow = inp$maj_j;
        end
        in_last = inp$maj_count == 32'h1;
        if (clip_y$on & (in_crow == 32'h0)) begin
            in_last = 1'b1;
        end
        in_short0_none = inp$short0_count == 32'h0;
        start_maj$up = in_up;
        start_maj$r = inp$maj_r;
        start_maj$rho = inp$maj_rho;
        start_maj$d = inp$maj_d;
        start_s0$up = in_up;
        start_s0$r = inp$short0_r;
        start_s0$rho = inp$short0_rho;
        start_s0$d = inp$short0_d;
        start_s1$up = in_up;
        start_s1$r = inp$short1_r;
        start_s1$rho = inp$short1_rho;
        start_s1$d = inp$short1_d;
        j_sign$x = j$q;
        j_next = j$q + 32'h1;
        if (up$q) begin
            j_next = j$q - 32'h1;
        end
        sides$a = cur$x;
        sides$b = maj$x;
        if (maj_left$q) begin
            sides$a = maj$x;
            sides$b = cur$x;
        end
        valid = sides$lt;
        if (clip_y$on & j_sign$neg) begin
            valid = 1'b0;
        end
        free = ~o_valid$q | out$ready;
        emit = walking$q & free;
        step = emit & ~last_r$q;
        if (free) begin
            o_valid$d = 1'b0;
        end
        if (emit) begin
            o_valid$d = valid;
            o_y$d = ((j$q) & 10'h3ff);
            if (maj_left$q) begin
                o_xl$d = maj$x;
                o_xr$d = cur$x - 32'h1;
                o_left_z$d = maj$at_z;
                o_left_c0$d = maj$at_c0;
                o_left_c1$d = maj$at_c1;
                o_left_c2$d = maj$at_c2;
                o_right_z$d = cur$at_z;
                o_right_c0$d = cur$at_c0;
                o_right_c1$d = cur$at_c1;
                o_right_c2$d = cur$at_c2;
            end
            else begin
                o_xl$d = cur$x;
                o_xr$d = maj$x - 32'h1;
                o_left_z$d = cur$at_z;
                o_left_c0$d = cur$at_c0;
                o_left_c1$d = cur$at_c1;
                o_left_c2$d = cur$at_c2;
                o_right_z$d = maj$at_z;
                o_right_c0$d = maj$at_c0;
                o_right_c1$d = maj$at_c1;
                o_right_c2$d = maj$at_c2;
            end
        end
        out$valid = o_valid$q;
        out$y = o_y$q;
        out$xl = o_xl$q;
        out$xr = o_xr$q;
        out$left_z = o_left_z$q;
        out$left_c0 = o_left_c0$q;
        out$left_c1 = o_left_c1$q;
        out$left_c2 = o_left_c2$q;
        out$right_z = o_right_z$q;
        out$right_c0 = o_right_c0$q;
        out$right_c1 = o_right_c1$q;
        out$right_c2 = o_right_c2$q;
        out$ddx_z = ddx_z$q;
        out$ddx_c0 = ddx_c0$q;
        out$ddx_c1 = ddx_c1$q;
        out$ddx_c2 = ddx_c2$q;
        maj$up = up$q;
        maj$load = accept;
        maj$step = step;
        cur$up = up$q;
        cur$load = accept | (step & sw_r$q);
        cur$step = step;
        maj$ld_x = inp$maj_x;
        maj$ld_q = ((inp$maj_q) & 13'h1fff);
        maj$ld_t = start_maj$t;
        maj$ld_a = start_maj$a;
        maj$ld_b = start_maj$b;
        maj$ld_at_z = inp$maj_at_z;
        maj$ld_at_c0 = inp$maj_at_c0;
        maj$ld_at_c1 = inp$maj_at_c1;
        maj$ld_at_c2 = inp$maj_at_c2;
        maj$ld_inc0_z = ((inp$maj_inc0_z) & 36'hfffffffff);
        maj$ld_inc0_c0 = ((inp$maj_inc0_c0) & 32'hffffffff);
        maj$ld_inc0_c1 = ((inp$maj_inc0_c1) & 32'hffffffff);
        maj$ld_inc0_c2 = ((inp$maj_inc0_c2) & 32'hffffffff);
        maj$ld_inc1_z = ((inp$maj_inc1_z) & 36'hfffffffff);
        maj$ld_inc1_c0 = ((inp$maj_inc1_c0) & 32'hffffffff);
        maj$ld_inc1_c1 = ((inp$maj_inc1_c1) & 32'hffffffff);
        maj$ld_inc1_c2 = ((inp$maj_inc1_c2) & 32'hffffffff);
        if (busy$q) begin
            cur$ld_x = pend_x$q;
            cur$ld_q = pend_q$q;
            cur$ld_t = pend_t$q;
            cur$ld_a = pend_a$q;
            cur$ld_b = pend_b$q;
            cur$ld_at_z = pend_at_z$q;
            cur$ld_at_c0 = pend_at_c0$q;
            cur$ld_at_c1 = pend_at_c1$q;
            cur$ld_at_c2 = pend_at_c2$q;
            cur$ld_inc0_z = pend_inc0_z$q;
            cur$ld_inc0_c0 = pend_inc0_c0$q;
            cur$ld_inc0_c1 = pend_inc0_c1$q;
            cur$ld_inc0_c2 = pend_inc0_c2$q;
            cur$ld_inc1_z = pend_inc1_z$q;
            cur$ld_inc1_c0 = pend_inc1_c0$q;
            cur$ld_inc1_c1 = pend_inc1_c1$q;
            cur$ld_inc1_c2 = pend_inc1_c2$q;
        end
        else if (in_short0_none) begin
            cur$ld_x = inp$short1_x;
            cur$ld_q = ((inp$short1_q) & 13'h1fff);
            cur$ld_t = start_s1$t;
            cur$ld_a = start_s1$a;
            cur$ld_b = start_s1$b;
            cur$ld_at_z = inp$short1_at_z;
            cur$ld_at_c0 = inp$short1_at_c0;
            cur$ld_at_c1 = inp$short1_at_c1;
            cur$ld_at_c2 = inp$short1_at_c2;
            cur$ld_inc0_z = ((inp$short1_inc0_z) & 36'hfffffffff);
            cur$ld_inc0_c0 = ((inp$short1_inc0_c0) & 32'hffffffff);
            cur$ld_inc0_c1 = ((inp$short1_inc0_c1) & 32'hffffffff);
            cur$ld_inc0_c2 = ((inp$short1_inc0_c2) & 32'hffffffff);
            cur$ld_inc1_z = ((inp$short1_inc1_z) & 36'hfffffffff);
            cur$ld_inc1_c0 = ((inp$short1_inc1_c0) & 32'hffffffff);
            cur$ld_inc1_c1 = ((inp$short1_inc1_c1) & 32'hffffffff);
            cur$ld_inc1_c2 = ((inp$short1_inc1_c2) & 32'hffffffff);
        end
        else begin
            cur$ld_x = inp$short0_x;
            cur$ld_q = ((inp$short0_q) & 13'h1fff);
            cur$ld_t = start_s0$t;
            cur$ld_a = start_s0$a;
            cur$ld_b = start_s0$b;
            cur$ld_at_z = inp$short0_at_z;
            cur$ld_at_c0 = inp$short0_at_c0;
            cur$ld_at_c1 = inp$short0_at_c1;
            cur$ld_at_c2 = inp$short0_at_c2;
            cur$ld_inc0_z = ((inp$short0_inc0_z) & 36'hfffffffff);
            cur$ld_inc0_c0 = ((inp$short0_inc0_c0) & 32'hffffffff);
            cur$ld_inc0_c1 = ((inp$short0_inc0_c1) & 32'hffffffff);
            cur$ld_inc0_c2 = ((inp$short0_inc0_c2) & 32'hffffffff);
            cur$ld_inc1_z = ((inp$short0_inc1_z) & 36'hfffffffff);
            cur$ld_inc1_c0 = ((inp$short0_inc1_c0) & 32'hffffffff);
            cur$ld_inc1_c1 = ((inp$short0_inc1_c1) & 32'hffffffff);
            cur$ld_inc1_c2 = ((inp$short0_inc1_c2) & 32'hffffffff);
        end
        if (step) begin
            j$d = j_next;
            rem$d = rem$q - 32'h1;
            crow$d = crow$q - 32'h1;
            crem$d = crem$q - 32'h1;
            last_r$d = rem$q == 32'h1;
            if (clip_y$on & (crow$q == 32'h1)) begin
                last_r$d = 1'b1;
            end
            sw_r$d = crem$q == 32'h1;
        end
        if (emit & last_r$q) begin
            walking$d = 1'b0;
        end
        if (busy$q & ~walking$q & free) begin
            busy$d = 1'b0;
        end
        if (accept) begin
            busy$d = 1'b1;
            walking$d = ~in_no_rows;
            up$d = in_up;
            maj_left$d = inp$maj_left;
            j$d = inp$maj_j;
            rem$d = inp$maj_count - 32'h1;
            crow$d = in_crow;
            crem$d = inp$short0_count - 32'h1;
            last_r$d = in_last;
            sw_r$d = inp$short0_count == 32'h1;
            ddx_z$d = inp$ddx_z;
            ddx_c0$d = inp$ddx_c0;
            ddx_c1$d = inp$ddx_c1;
            ddx_c2$d = inp$ddx_c2;
            pend_x$d = inp$short1_x;
            pend_q$d = ((inp$short1_q) & 13'h1fff);
            pend_t$d = start_s1$t;
            pend_a$d = start_s1$a;
            pend_b$d = start_s1$b;
            pend_at_z$d = inp$short1_at_z;
            pend_at_c0$d = inp$short1_at_c0;
            pend_at_c1$d = inp$short1_at_c1;
            pend_at_c2$d = inp$short1_at_c2;
            pend_inc0_z$d = ((inp$short1_inc0_z) & 36'hfffffffff);
            pend_inc0_c0$d = ((inp$short1_inc0_c0) & 32'hffffffff);
            pend_inc0_c1$d = ((inp$short1_inc0_c1) & 32'hffffffff);
            pend_inc0_c2$d = ((inp$short1_inc0_c2) & 32'hffffffff);
            pend_inc1_z$d = ((inp$short1_inc1_z) & 36'hfffffffff);
            pend_inc1_c0$d = ((inp$short1_inc1_c0) & 32'hffffffff);
            pend_inc1_c1$d = ((inp$short1_inc1_c1) & 32'hffffffff);
            pend_inc1_c2$d = ((inp$short1_inc1_c2) & 32'hffffffff);
        end
        free_next = ~busy$q | (~walking$q & free);
        if (accept) begin
            free_next = 1'b0;
        end
    end
    
endmodule // raster_top$fragments$core$edge_walk


module raster_top$fragments$core$edge_walk$busy(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$busy


module raster_top$fragments$core$edge_walk$clip_y(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // raster_top$fragments$core$edge_walk$clip_y


module raster_top$fragments$core$edge_walk$crem(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$crem


module raster_top$fragments$core$edge_walk$crow(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$crow


module raster_top$fragments$core$edge_walk$cur(clock,load,step,up,ld_x,ld_q,ld_t,ld_a,ld_b,ld_at_z,ld_at_c0,ld_at_c1,ld_at_c2,ld_inc0_z,ld_inc0_c0,ld_inc0_c1,ld_inc0_c2,ld_inc1_z,ld_inc1_c0,ld_inc1_c1,ld_inc1_c2,x,at_z,at_c0,at_c1,at_c2);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  [12:0] ld_x;
    input wire  [12:0] ld_q;
    input wire  [21:0] ld_t;
    input wire  [21:0] ld_a;
    input wire  [21:0] ld_b;
    input wire  [35:0] ld_at_z;
    input wire  [31:0] ld_at_c0;
    input wire  [31:0] ld_at_c1;
    input wire  [31:0] ld_at_c2;
    input wire  [35:0] ld_inc0_z;
    input wire  [31:0] ld_inc0_c0;
    input wire  [31:0] ld_inc0_c1;
    input wire  [31:0] ld_inc0_c2;
    input wire  [35:0] ld_inc1_z;
    input wire  [31:0] ld_inc1_c0;
    input wire  [31:0] ld_inc1_c1;
    input wire  [31:0] ld_inc1_c2;
    output reg  [12:0] x;
    output reg  [35:0] at_z;
    output reg  [31:0] at_c0;
    output reg  [31:0] at_c1;
    output reg  [31:0] at_c2;
    
    // Stub signals
    reg  [12:0] x_r$d;
    wire  [12:0] x_r$q;
    reg  x_r$clock;
    reg  [12:0] q_r$d;
    wire  [12:0] q_r$q;
    reg  q_r$clock;
    reg  [21:0] t_r$d;
    wire  [21:0] t_r$q;
    reg  t_r$clock;
    reg  [21:0] a_r$d;
    wire  [21:0] a_r$q;
    reg  a_r$clock;
    reg  [21:0] b_r$d;
    wire  [21:0] b_r$q;
    reg  b_r$clock;
    reg  z$clock;
    reg  z$load;
    reg  z$step;
    reg  z$up;
    reg  z$one;
    reg  [35:0] z$ld_at;
    reg  [35:0] z$ld_inc0;
    reg  [35:0] z$ld_inc1;
    wire  [35:0] z$at;
    reg  c0$clock;
    reg  c0$load;
    reg  c0$step;
    reg  c0$up;
    reg  c0$one;
    reg  [31:0] c0$ld_at;
    reg  [31:0] c0$ld_inc0;
    reg  [31:0] c0$ld_inc1;
    wire  [31:0] c0$at;
    reg  c1$clock;
    reg  c1$load;
    reg  c1$step;
    reg  c1$up;
    reg  c1$one;
    reg  [31:0] c1$ld_at;
    reg  [31:0] c1$ld_inc0;
    reg  [31:0] c1$ld_inc1;
    wire  [31:0] c1$at;
    reg  c2$clock;
    reg  c2$load;
    reg  c2$step;
    reg  c2$up;
    reg  c2$one;
    reg  [31:0] c2$ld_at;
    reg  [31:0] c2$ld_inc0;
    reg  [31:0] c2$ld_inc1;
    wire  [31:0] c2$at;
    reg  [21:0] t_sign$x;
    wire  t_sign$neg;
    
    // Local signals
    reg  one;
    reg  [21:0] t_inc;
    reg  [12:0] q_dir;
    reg  one_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$cur$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$q_r q_r(
        .d(q_r$d),
        .q(q_r$q),
        .clock(q_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$t_r t_r(
        .d(t_r$d),
        .q(t_r$q),
        .clock(t_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$z z(
        .clock(z$clock),
        .load(z$load),
        .step(z$step),
        .up(z$up),
        .one(z$one),
        .ld_at(z$ld_at),
        .ld_inc0(z$ld_inc0),
        .ld_inc1(z$ld_inc1),
        .at(z$at)
    );
    raster_top$fragments$core$edge_walk$cur$c0 c0(
        .clock(c0$clock),
        .load(c0$load),
        .step(c0$step),
        .up(c0$up),
        .one(c0$one),
        .ld_at(c0$ld_at),
        .ld_inc0(c0$ld_inc0),
        .ld_inc1(c0$ld_inc1),
        .at(c0$at)
    );
    raster_top$fragments$core$edge_walk$cur$c1 c1(
        .clock(c1$clock),
        .load(c1$load),
        .step(c1$step),
        .up(c1$up),
        .one(c1$one),
        .ld_at(c1$ld_at),
        .ld_inc0(c1$ld_inc0),
        .ld_inc1(c1$ld_inc1),
        .at(c1$at)
    );
    raster_top$fragments$core$edge_walk$cur$c2 c2(
        .clock(c2$clock),
        .load(c2$load),
        .step(c2$step),
        .up(c2$up),
        .one(c2$one),
        .ld_at(c2$ld_at),
        .ld_inc0(c2$ld_inc0),
        .ld_inc1(c2$ld_inc1),
        .at(c2$at)
    );
    raster_top$fragments$core$edge_walk$cur$t_sign t_sign(
        .x(t_sign$x),
        .neg(t_sign$neg)
    );
    
    // Update code
    always @(*) begin
        x_r$clock = clock;
        q_r$clock = clock;
        t_r$clock = clock;
        a_r$clock = clock;
        b_r$clock = clock;
        x_r$d = x_r$q;
        q_r$d = q_r$q;
        t_r$d = t_r$q;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        z$clock = clock;
        c0$clock = clock;
        c1$clock = clock;
        c2$clock = clock;
        t_sign$x = t_r$q;
        one = t_sign$neg;
        t_inc = b_r$q;
        if (one) begin
            t_inc = a_r$q;
        end
        q_dir = q_r$q;
        one_dir = one;
        if (up) begin
            q_dir = ~q_r$q;
            one_dir = ~one;
        end
        if (step) begin
            t_r$d = t_r$q + t_inc;
            x_r$d = x_r$q + q_dir + one_dir;
        end
        if (load) begin
            x_r$d = ld_x;
            q_r$d = ld_q;
            t_r$d = ld_t;
            a_r$d = ld_a;
            b_r$d = ld_b;
        end
        z$load = load;
        z$step = step;
        z$up = up;
        z$one = one;
        z$ld_at = ld_at_z;
        z$ld_inc0 = ld_inc0_z;
        z$ld_inc1 = ld_inc1_z;
        c0$load = load;
        c0$step = step;
        c0$up = up;
        c0$one = one;
        c0$ld_at = ld_at_c0;
        c0$ld_inc0 = ld_inc0_c0;
        c0$ld_inc1 = ld_inc1_c0;
        c1$load = load;
        c1$step = step;
        c1$up = up;
        c1$one = one;
        c1$ld_at = ld_at_c1;
        c1$ld_inc0 = ld_inc0_c1;
        c1$ld_inc1 = ld_inc1_c1;
        c2$load = load;
        c2$step = step;
        c2$up = up;
        c2$one = one;
        c2$ld_at = ld_at_c2;
        c2$ld_inc0 = ld_inc0_c2;
        c2$ld_inc1 = ld_inc1_c2;
        x = x_r$q;
        at_z = z$at;
        at_c0 = c0$at;
        at_c1 = c1$at;
        at_c2 = c2$at;
    end
    
endmodule // raster_top$fragments$core$edge_walk$cur


module raster_top$fragments$core$edge_walk$cur$a_r(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$a_r


module raster_top$fragments$core$edge_walk$cur$b_r(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$b_r


module raster_top$fragments$core$edge_walk$cur$c0(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$cur$c0$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$c0$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$c0$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // raster_top$fragments$core$edge_walk$cur$c0


module raster_top$fragments$core$edge_walk$cur$c0$at_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c0$at_r


module raster_top$fragments$core$edge_walk$cur$c0$inc0_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c0$inc0_r


module raster_top$fragments$core$edge_walk$cur$c0$inc1_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c0$inc1_r


module raster_top$fragments$core$edge_walk$cur$c1(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$cur$c1$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$c1$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$c1$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // raster_top$fragments$core$edge_walk$cur$c1


module raster_top$fragments$core$edge_walk$cur$c1$at_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c1$at_r


module raster_top$fragments$core$edge_walk$cur$c1$inc0_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c1$inc0_r


module raster_top$fragments$core$edge_walk$cur$c1$inc1_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c1$inc1_r


module raster_top$fragments$core$edge_walk$cur$c2(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$cur$c2$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$c2$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$c2$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // raster_top$fragments$core$edge_walk$cur$c2


module raster_top$fragments$core$edge_walk$cur$c2$at_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c2$at_r


module raster_top$fragments$core$edge_walk$cur$c2$inc0_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c2$inc0_r


module raster_top$fragments$core$edge_walk$cur$c2$inc1_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$c2$inc1_r


module raster_top$fragments$core$edge_walk$cur$q_r(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$q_r


module raster_top$fragments$core$edge_walk$cur$t_r(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$t_r


module raster_top$fragments$core$edge_walk$cur$t_sign(x,neg);
    
    // Module arguments
    input wire  [21:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 22'h200000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$edge_walk$cur$t_sign


module raster_top$fragments$core$edge_walk$cur$x_r(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$x_r


module raster_top$fragments$core$edge_walk$cur$z(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [35:0] ld_at;
    input wire  [35:0] ld_inc0;
    input wire  [35:0] ld_inc1;
    output reg  [35:0] at;
    
    // Stub signals
    reg  [35:0] at_r$d;
    wire  [35:0] at_r$q;
    reg  at_r$clock;
    reg  [35:0] inc0_r$d;
    wire  [35:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [35:0] inc1_r$d;
    wire  [35:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [35:0] inc;
    reg  [35:0] inc_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$cur$z$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$z$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    raster_top$fragments$core$edge_walk$cur$z$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // raster_top$fragments$core$edge_walk$cur$z


module raster_top$fragments$core$edge_walk$cur$z$at_r(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$z$at_r


module raster_top$fragments$core$edge_walk$cur$z$inc0_r(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$z$inc0_r


module raster_top$fragments$core$edge_walk$cur$z$inc1_r(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$cur$z$inc1_r


module raster_top$fragments$core$edge_walk$ddx_c0(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$ddx_c0


module raster_top$fragments$core$edge_walk$ddx_c1(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$ddx_c1


module raster_top$fragments$core$edge_walk$ddx_c2(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$ddx_c2


module raster_top$fragments$core$edge_walk$ddx_z(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$ddx_z


module raster_top$fragments$core$edge_walk$in_j_sign(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$edge_walk$in_j_sign


module raster_top$fragments$core$edge_walk$j(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$j


module raster_top$fragments$core$edge_walk$j_sign(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$edge_walk$j_sign


module raster_top$fragments$core$edge_walk$last_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$last_r


module raster_top$fragments$core$edge_walk$maj(clock,load,step,up,ld_x,ld_q,ld_t,ld_a,ld_b,ld_at_z,ld_at_c0,ld_at_c1,ld_at_c2,ld_inc0_z,ld_inc0_c0,ld_inc0_c1,ld_inc0_c2,ld_inc1_z,ld_inc1_c0,ld_inc1_c1,ld_inc1_c2,x,at_z,at_c0,at_c1,at_c2);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  [12:0] ld_x;
    input wire  [12:0] ld_q;
    input wire  [21:0] ld_t;
    input wire  [21:0] ld_a;
    input wire  [21:0] ld_b;
    input wire  [35:0] ld_at_z;
    input wire  [31:0] ld_at_c0;
    input wire  [31:0] ld_at_c1;
    input wire  [31:0] ld_at_c2;
    input wire  [35:0] ld_inc0_z;
    input wire  [31:0] ld_inc0_c0;
    input wire  [31:0] ld_inc0_c1;
    input wire  [31:0] ld_inc0_c2;
    input wire  [35:0] ld_inc1_z;
    input wire  [31:0] ld_inc1_c0;
    input wire  [31:0] ld_inc1_c1;
    input wire  [31:0] ld_inc1_c2;
    output reg  [12:0] x;
    output reg  [35:0] at_z;
    output reg  [31:0] at_c0;
    output reg  [31:0] at_c1;
    output reg  [31:0] at_c2;
    
    // Stub signals
    reg  [12:0] x_r$d;
    wire  [12:0] x_r$q;
    reg  x_r$clock;
    reg  [12:0] q_r$d;
    wire  [12:0] q_r$q;
    reg  q_r$clock;
    reg  [21:0] t_r$d;
    wire  [21:0] t_r$q;
    reg  t_r$clock;
    reg  [21:0] a_r$d;
    wire  [21:0] a_r$q;
    reg  a_r$clock;
    reg  [21:0] b_r$d;
    wire  [21:0] b_r$q;
    reg  b_r$clock;
    reg  z$clock;
    reg  z$load;
    reg  z$step;
    reg  z$up;
    reg  z$one;
    reg  [35:0] z$ld_at;
    reg  [35:0] z$ld_inc0;
    reg  [35:0] z$ld_inc1;
    wire  [35:0] z$at;
    reg  c0$clock;
    reg  c0$load;
    reg  c0$step;
    reg  c0$up;
    reg  c0$one;
    reg  [31:0] c0$ld_at;
    reg  [31:0] c0$ld_inc0;
    reg  [31:0] c0$ld_inc1;
    wire  [31:0] c0$at;
    reg  c1$clock;
    reg  c1$load;
    reg  c1$step;
    reg  c1$up;
    reg  c1$one;
    reg  [31:0] c1$ld_at;
    reg  [31:0] c1$ld_inc0;
    reg  [31:0] c1$ld_inc1;
    wire  [31:0] c1$at;
    reg  c2$clock;
    reg  c2$load;
    reg  c2$step;
    reg  c2$up;
    reg  c2$one;
    reg  [31:0] c2$ld_at;
    reg  [31:0] c2$ld_inc0;
    reg  [31:0] c2$ld_inc1;
    wire  [31:0] c2$at;
    reg  [21:0] t_sign$x;
    wire  t_sign$neg;
    
    // Local signals
    reg  one;
    reg  [21:0] t_inc;
    reg  [12:0] q_dir;
    reg  one_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$maj$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$q_r q_r(
        .d(q_r$d),
        .q(q_r$q),
        .clock(q_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$t_r t_r(
        .d(t_r$d),
        .q(t_r$q),
        .clock(t_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$a_r a_r(
        .d(a_r$d),
        .q(a_r$q),
        .clock(a_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$z z(
        .clock(z$clock),
        .load(z$load),
        .step(z$step),
        .up(z$up),
        .one(z$one),
        .ld_at(z$ld_at),
        .ld_inc0(z$ld_inc0),
        .ld_inc1(z$ld_inc1),
        .at(z$at)
    );
    raster_top$fragments$core$edge_walk$maj$c0 c0(
        .clock(c0$clock),
        .load(c0$load),
        .step(c0$step),
        .up(c0$up),
        .one(c0$one),
        .ld_at(c0$ld_at),
        .ld_inc0(c0$ld_inc0),
        .ld_inc1(c0$ld_inc1),
        .at(c0$at)
    );
    raster_top$fragments$core$edge_walk$maj$c1 c1(
        .clock(c1$clock),
        .load(c1$load),
        .step(c1$step),
        .up(c1$up),
        .one(c1$one),
        .ld_at(c1$ld_at),
        .ld_inc0(c1$ld_inc0),
        .ld_inc1(c1$ld_inc1),
        .at(c1$at)
    );
    raster_top$fragments$core$edge_walk$maj$c2 c2(
        .clock(c2$clock),
        .load(c2$load),
        .step(c2$step),
        .up(c2$up),
        .one(c2$one),
        .ld_at(c2$ld_at),
        .ld_inc0(c2$ld_inc0),
        .ld_inc1(c2$ld_inc1),
        .at(c2$at)
    );
    raster_top$fragments$core$edge_walk$maj$t_sign t_sign(
        .x(t_sign$x),
        .neg(t_sign$neg)
    );
    
    // Update code
    always @(*) begin
        x_r$clock = clock;
        q_r$clock = clock;
        t_r$clock = clock;
        a_r$clock = clock;
        b_r$clock = clock;
        x_r$d = x_r$q;
        q_r$d = q_r$q;
        t_r$d = t_r$q;
        a_r$d = a_r$q;
        b_r$d = b_r$q;
        z$clock = clock;
        c0$clock = clock;
        c1$clock = clock;
        c2$clock = clock;
        t_sign$x = t_r$q;
        one = t_sign$neg;
        t_inc = b_r$q;
        if (one) begin
            t_inc = a_r$q;
        end
        q_dir = q_r$q;
        one_dir = one;
        if (up) begin
            q_dir = ~q_r$q;
            one_dir = ~one;
        end
        if (step) begin
            t_r$d = t_r$q + t_inc;
            x_r$d = x_r$q + q_dir + one_dir;
        end
        if (load) begin
            x_r$d = ld_x;
            q_r$d = ld_q;
            t_r$d = ld_t;
            a_r$d = ld_a;
            b_r$d = ld_b;
        end
        z$load = load;
        z$step = step;
        z$up = up;
        z$one = one;
        z$ld_at = ld_at_z;
        z$ld_inc0 = ld_inc0_z;
        z$ld_inc1 = ld_inc1_z;
        c0$load = load;
        c0$step = step;
        c0$up = up;
        c0$one = one;
        c0$ld_at = ld_at_c0;
        c0$ld_inc0 = ld_inc0_c0;
        c0$ld_inc1 = ld_inc1_c0;
        c1$load = load;
        c1$step = step;
        c1$up = up;
        c1$one = one;
        c1$ld_at = ld_at_c1;
        c1$ld_inc0 = ld_inc0_c1;
        c1$ld_inc1 = ld_inc1_c1;
        c2$load = load;
        c2$step = step;
        c2$up = up;
        c2$one = one;
        c2$ld_at = ld_at_c2;
        c2$ld_inc0 = ld_inc0_c2;
        c2$ld_inc1 = ld_inc1_c2;
        x = x_r$q;
        at_z = z$at;
        at_c0 = c0$at;
        at_c1 = c1$at;
        at_c2 = c2$at;
    end
    
endmodule // raster_top$fragments$core$edge_walk$maj


module raster_top$fragments$core$edge_walk$maj$a_r(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$a_r


module raster_top$fragments$core$edge_walk$maj$b_r(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$b_r


module raster_top$fragments$core$edge_walk$maj$c0(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$maj$c0$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$c0$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$c0$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // raster_top$fragments$core$edge_walk$maj$c0


module raster_top$fragments$core$edge_walk$maj$c0$at_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c0$at_r


module raster_top$fragments$core$edge_walk$maj$c0$inc0_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c0$inc0_r


module raster_top$fragments$core$edge_walk$maj$c0$inc1_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c0$inc1_r


module raster_top$fragments$core$edge_walk$maj$c1(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$maj$c1$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$c1$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$c1$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // raster_top$fragments$core$edge_walk$maj$c1


module raster_top$fragments$core$edge_walk$maj$c1$at_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c1$at_r


module raster_top$fragments$core$edge_walk$maj$c1$inc0_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c1$inc0_r


module raster_top$fragments$core$edge_walk$maj$c1$inc1_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c1$inc1_r


module raster_top$fragments$core$edge_walk$maj$c2(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [31:0] ld_at;
    input wire  [31:0] ld_inc0;
    input wire  [31:0] ld_inc1;
    output reg  [31:0] at;
    
    // Stub signals
    reg  [31:0] at_r$d;
    wire  [31:0] at_r$q;
    reg  at_r$clock;
    reg  [31:0] inc0_r$d;
    wire  [31:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [31:0] inc1_r$d;
    wire  [31:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [31:0] inc;
    reg  [31:0] inc_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$maj$c2$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$c2$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$c2$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // raster_top$fragments$core$edge_walk$maj$c2


module raster_top$fragments$core$edge_walk$maj$c2$at_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c2$at_r


module raster_top$fragments$core$edge_walk$maj$c2$inc0_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c2$inc0_r


module raster_top$fragments$core$edge_walk$maj$c2$inc1_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$c2$inc1_r


module raster_top$fragments$core$edge_walk$maj$q_r(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$q_r


module raster_top$fragments$core$edge_walk$maj$t_r(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$t_r


module raster_top$fragments$core$edge_walk$maj$t_sign(x,neg);
    
    // Module arguments
    input wire  [21:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 22'h200000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$edge_walk$maj$t_sign


module raster_top$fragments$core$edge_walk$maj$x_r(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$x_r


module raster_top$fragments$core$edge_walk$maj$z(clock,load,step,up,one,ld_at,ld_inc0,ld_inc1,at);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  step;
    input wire  up;
    input wire  one;
    input wire  [35:0] ld_at;
    input wire  [35:0] ld_inc0;
    input wire  [35:0] ld_inc1;
    output reg  [35:0] at;
    
    // Stub signals
    reg  [35:0] at_r$d;
    wire  [35:0] at_r$q;
    reg  at_r$clock;
    reg  [35:0] inc0_r$d;
    wire  [35:0] inc0_r$q;
    reg  inc0_r$clock;
    reg  [35:0] inc1_r$d;
    wire  [35:0] inc1_r$q;
    reg  inc1_r$clock;
    
    // Local signals
    reg  [35:0] inc;
    reg  [35:0] inc_dir;
    
    // Sub module instances
    raster_top$fragments$core$edge_walk$maj$z$at_r at_r(
        .d(at_r$d),
        .q(at_r$q),
        .clock(at_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$z$inc0_r inc0_r(
        .d(inc0_r$d),
        .q(inc0_r$q),
        .clock(inc0_r$clock)
    );
    raster_top$fragments$core$edge_walk$maj$z$inc1_r inc1_r(
        .d(inc1_r$d),
        .q(inc1_r$q),
        .clock(inc1_r$clock)
    );
    
    // Update code
    always @(*) begin
        at_r$clock = clock;
        inc0_r$clock = clock;
        inc1_r$clock = clock;
        at_r$d = at_r$q;
        inc0_r$d = inc0_r$q;
        inc1_r$d = inc1_r$q;
        inc = inc0_r$q;
        if (one) begin
            inc = inc1_r$q;
        end
        inc_dir = inc;
        if (up) begin
            inc_dir = ~inc;
        end
        if (step) begin
            at_r$d = at_r$q + inc_dir + up;
        end
        if (load) begin
            at_r$d = ld_at;
            inc0_r$d = ld_inc0;
            inc1_r$d = ld_inc1;
        end
        at = at_r$q;
    end
    
endmodule // raster_top$fragments$core$edge_walk$maj$z


module raster_top$fragments$core$edge_walk$maj$z$at_r(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$z$at_r


module raster_top$fragments$core$edge_walk$maj$z$inc0_r(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$z$inc0_r


module raster_top$fragments$core$edge_walk$maj$z$inc1_r(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj$z$inc1_r


module raster_top$fragments$core$edge_walk$maj_left(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$maj_left


module raster_top$fragments$core$edge_walk$o_left_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_left_c0


module raster_top$fragments$core$edge_walk$o_left_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_left_c1


module raster_top$fragments$core$edge_walk$o_left_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_left_c2


module raster_top$fragments$core$edge_walk$o_left_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_left_z


module raster_top$fragments$core$edge_walk$o_right_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_right_c0


module raster_top$fragments$core$edge_walk$o_right_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_right_c1


module raster_top$fragments$core$edge_walk$o_right_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_right_c2


module raster_top$fragments$core$edge_walk$o_right_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_right_z


module raster_top$fragments$core$edge_walk$o_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_valid


module raster_top$fragments$core$edge_walk$o_xl(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_xl


module raster_top$fragments$core$edge_walk$o_xr(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_xr


module raster_top$fragments$core$edge_walk$o_y(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$o_y


module raster_top$fragments$core$edge_walk$pend_a(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_a


module raster_top$fragments$core$edge_walk$pend_at_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_at_c0


module raster_top$fragments$core$edge_walk$pend_at_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_at_c1


module raster_top$fragments$core$edge_walk$pend_at_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_at_c2


module raster_top$fragments$core$edge_walk$pend_at_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_at_z


module raster_top$fragments$core$edge_walk$pend_b(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_b


module raster_top$fragments$core$edge_walk$pend_inc0_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_inc0_c0


module raster_top$fragments$core$edge_walk$pend_inc0_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_inc0_c1


module raster_top$fragments$core$edge_walk$pend_inc0_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_inc0_c2


module raster_top$fragments$core$edge_walk$pend_inc0_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_inc0_z


module raster_top$fragments$core$edge_walk$pend_inc1_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_inc1_c0


module raster_top$fragments$core$edge_walk$pend_inc1_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_inc1_c1


module raster_top$fragments$core$edge_walk$pend_inc1_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_inc1_c2


module raster_top$fragments$core$edge_walk$pend_inc1_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_inc1_z


module raster_top$fragments$core$edge_walk$pend_q(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_q


module raster_top$fragments$core$edge_walk$pend_t(d,q,clock);
    
    // Module arguments
    input wire  [21:0] d;
    output reg  [21:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 22'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_t


module raster_top$fragments$core$edge_walk$pend_x(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$pend_x


module raster_top$fragments$core$edge_walk$rem(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$rem


module raster_top$fragments$core$edge_walk$sides(a,b,lt);
    
    // Module arguments
    input wire  [12:0] a;
    input wire  [12:0] b;
    output reg  lt;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        lt = (a ^ half) < (b ^ half);
    end
    
endmodule // raster_top$fragments$core$edge_walk$sides


module raster_top$fragments$core$edge_walk$start_maj(up,r,rho,d,t,a,b);
    
    // Module arguments
    input wire  up;
    input wire  [20:0] r;
    input wire  [20:0] rho;
    input wire  [20:0] d;
    output reg  [21:0] t;
    output reg  [21:0] a;
    output reg  [21:0] b;
    
    // Local signals
    reg  [21:0] r_w;
    reg  [21:0] rho_w;
    reg  [21:0] d_w;
    reg  [21:0] nr;
    reg  [21:0] nrho;
    reg  [21:0] sum;
    reg  [21:0] carry;
    
    // Update code
    always @(*) begin
        r_w = ((r) & 22'h3fffff);
        rho_w = ((rho) & 22'h3fffff);
        d_w = ((d) & 22'h3fffff);
        a = d_w - rho_w;
        b = ~rho_w + 32'h1;
        nr = ~r_w;
        nrho = ~rho_w;
        sum = d_w ^ nr ^ nrho;
        carry = (d_w & nr) | (d_w & nrho) | (nr & nrho);
        t = r_w - rho_w;
        if (up) begin
            t = sum + ((carry << 32'h1) | 32'h1);
        end
    end
    
endmodule // raster_top$fragments$core$edge_walk$start_maj


module raster_top$fragments$core$edge_walk$start_s0(up,r,rho,d,t,a,b);
    
    // Module arguments
    input wire  up;
    input wire  [20:0] r;
    input wire  [20:0] rho;
    input wire  [20:0] d;
    output reg  [21:0] t;
    output reg  [21:0] a;
    output reg  [21:0] b;
    
    // Local signals
    reg  [21:0] r_w;
    reg  [21:0] rho_w;
    reg  [21:0] d_w;
    reg  [21:0] nr;
    reg  [21:0] nrho;
    reg  [21:0] sum;
    reg  [21:0] carry;
    
    // Update code
    always @(*) begin
        r_w = ((r) & 22'h3fffff);
        rho_w = ((rho) & 22'h3fffff);
        d_w = ((d) & 22'h3fffff);
        a = d_w - rho_w;
        b = ~rho_w + 32'h1;
        nr = ~r_w;
        nrho = ~rho_w;
        sum = d_w ^ nr ^ nrho;
        carry = (d_w & nr) | (d_w & nrho) | (nr & nrho);
        t = r_w - rho_w;
        if (up) begin
            t = sum + ((carry << 32'h1) | 32'h1);
        end
    end
    
endmodule // raster_top$fragments$core$edge_walk$start_s0


module raster_top$fragments$core$edge_walk$start_s1(up,r,rho,d,t,a,b);
    
    // Module arguments
    input wire  up;
    input wire  [20:0] r;
    input wire  [20:0] rho;
    input wire  [20:0] d;
    output reg  [21:0] t;
    output reg  [21:0] a;
    output reg  [21:0] b;
    
    // Local signals
    reg  [21:0] r_w;
    reg  [21:0] rho_w;
    reg  [21:0] d_w;
    reg  [21:0] nr;
    reg  [21:0] nrho;
    reg  [21:0] sum;
    reg  [21:0] carry;
    
    // Update code
    always @(*) begin
        r_w = ((r) & 22'h3fffff);
        rho_w = ((rho) & 22'h3fffff);
        d_w = ((d) & 22'h3fffff);
        a = d_w - rho_w;
        b = ~rho_w + 32'h1;
        nr = ~r_w;
        nrho = ~rho_w;
        sum = d_w ^ nr ^ nrho;
        carry = (d_w & nr) | (d_w & nrho) | (nr & nrho);
        t = r_w - rho_w;
        if (up) begin
            t = sum + ((carry << 32'h1) | 32'h1);
        end
    end
    
endmodule // raster_top$fragments$core$edge_walk$start_s1


module raster_top$fragments$core$edge_walk$sw_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$sw_r


module raster_top$fragments$core$edge_walk$up(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$up


module raster_top$fragments$core$edge_walk$walking(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$edge_walk$walking


module raster_top$fragments$core$fifo(clock,inp$valid,inp$ready,inp$y,inp$xl,inp$xr,inp$left_z,inp$left_c0,inp$left_c1,inp$left_c2,inp$right_z,inp$right_c0,inp$right_c1,inp$right_c2,inp$ddx_z,inp$ddx_c0,inp$ddx_c1,inp$ddx_c2,out$valid,out$ready,out$y,out$xl,out$xr,out$left_z,out$left_c0,out$left_c1,out$left_c2,out$right_z,out$right_c0,out$right_c1,out$right_c2,out$ddx_z,out$ddx_c0,out$ddx_c1,out$ddx_c2,empty);
    
    // Module arguments
    input wire  clock;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$y;
    input wire  [12:0] inp$xl;
    input wire  [12:0] inp$xr;
    input wire  [35:0] inp$left_z;
    input wire  [31:0] inp$left_c0;
    input wire  [31:0] inp$left_c1;
    input wire  [31:0] inp$left_c2;
    input wire  [35:0] inp$right_z;
    input wire  [31:0] inp$right_c0;
    input wire  [31:0] inp$right_c1;
    input wire  [31:0] inp$right_c2;
    input wire  [39:0] inp$ddx_z;
    input wire  [35:0] inp$ddx_c0;
    input wire  [35:0] inp$ddx_c1;
    input wire  [35:0] inp$ddx_c2;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [9:0] out$y;
    output reg  [12:0] out$xl;
    output reg  [12:0] out$xr;
    output reg  [35:0] out$left_z;
    output reg  [31:0] out$left_c0;
    output reg  [31:0] out$left_c1;
    output reg  [31:0] out$left_c2;
    output reg  [35:0] out$right_z;
    output reg  [31:0] out$right_c0;
    output reg  [31:0] out$right_c1;
    output reg  [31:0] out$right_c2;
    output reg  [39:0] out$ddx_z;
    output reg  [35:0] out$ddx_c0;
    output reg  [35:0] out$ddx_c1;
    output reg  [35:0] out$ddx_c2;
    output reg  empty;
    
    // Constant declarations
    localparam  depth = 3'b100;
    
    // Stub signals
    reg  [2:0] count$d;
    wire  [2:0] count$q;
    reg  count$clock;
    reg  full$d;
    wire  full$q;
    reg  full$clock;
    reg  held$d;
    wire  held$q;
    reg  held$clock;
    reg  one$d;
    wire  one$q;
    reg  one$clock;
    reg  [1:0] wr$d;
    wire  [1:0] wr$q;
    reg  wr$clock;
    reg  [1:0] rd$d;
    wire  [1:0] rd$q;
    reg  rd$clock;
    reg  y$clock;
    reg  y$we;
    reg  [1:0] y$wr;
    reg  [1:0] y$rd;
    reg  y$take_din;
    reg  y$take_next;
    reg  [9:0] y$din;
    wire  [9:0] y$head;
    reg  xl$clock;
    reg  xl$we;
    reg  [1:0] xl$wr;
    reg  [1:0] xl$rd;
    reg  xl$take_din;
    reg  xl$take_next;
    reg  [12:0] xl$din;
    wire  [12:0] xl$head;
    reg  xr$clock;
    reg  xr$we;
    reg  [1:0] xr$wr;
    reg  [1:0] xr$rd;
    reg  xr$take_din;
    reg  xr$take_next;
    reg  [12:0] xr$din;
    wire  [12:0] xr$head;
    reg  left_z$clock;
    reg  left_z$we;
    reg  [1:0] left_z$wr;
    reg  [1:0] left_z$rd;
    reg  left_z$take_din;
    reg  left_z$take_next;
    reg  [35:0] left_z$din;
    wire  [35:0] left_z$head;
    reg  left_c0$clock;
    reg  left_c0$we;
    reg  [1:0] left_c0$wr;
    reg  [1:0] left_c0$rd;
    reg  left_c0$take_din;
    reg  left_c0$take_next;
    reg  [31:0] left_c0$din;
    wire  [31:0] left_c0$head;
    reg  left_c1$clock;
    reg  left_c1$we;
    reg  [1:0] left_c1$wr;
    reg  [1:0] left_c1$rd;
    reg  left_c1$take_din;
    reg  left_c1$take_next;
    reg  [31:0] left_c1$din;
    wire  [31:0] left_c1$head;
    reg  left_c2$clock;
    reg  left_c2$we;
    reg  [1:0] left_c2$wr;
    reg  [1:0] left_c2$rd;
    reg  left_c2$take_din;
    reg  left_c2$take_next;
    reg  [31:0] left_c2$din;
    wire  [31:0] left_c2$head;
    reg  right_z$clock;
    reg  right_z$we;
    reg  [1:0] right_z$wr;
    reg  [1:0] right_z$rd;
    reg  right_z$take_din;
    reg  right_z$take_next;
    reg  [35:0] right_z$din;
    wire  [35:0] right_z$head;
    reg  right_c0$clock;
    reg  right_c0$we;
    reg  [1:0] right_c0$wr;
    reg  [1:0] right_c0$rd;
    reg  right_c0$take_din;
    reg  right_c0$take_next;
    reg  [31:0] right_c0$din;
    wire  [31:0] right_c0$head;
    reg  right_c1$clock;
    reg  right_c1$we;
    reg  [1:0] right_c1$wr;
    reg  [1:0] right_c1$rd;
    reg  right_c1$take_din;
    reg  right_c1$take_next;
    reg  [31:0] right_c1$din;
    wire  [31:0] right_c1$head;
    reg  right_c2$clock;
    reg  right_c2$we;
    reg  [1:0] right_c2$wr;
    reg  [1:0] right_c2$rd;
    reg  right_c2$take_din;
    reg  right_c2$take_next;
    reg  [31:0] right_c2$din;
    wire  [31:0] right_c2$head;
    reg  ddx_z$clock;
    reg  ddx_z$we;
    reg  [1:0] ddx_z$wr;
    reg  [1:0] ddx_z$rd;
    reg  ddx_z$take_din;
    reg  ddx_z$take_next;
    reg  [39:0] ddx_z$din;
    wire  [39:0] ddx_z$head;
    reg  ddx_c0$clock;
    reg  ddx_c0$we;
    reg  [1:0] ddx_c0$wr;
    reg  [1:0] ddx_c0$rd;
    reg  ddx_c0$take_din;
    reg  ddx_c0$take_next;
    reg  [35:0] ddx_c0$din;
    wire  [35:0] ddx_c0$head;
    reg  ddx_c1$clock;
    reg  ddx_c1$we;
    reg  [1:0] ddx_c1$wr;
    reg  [1:0] ddx_c1$rd;
    reg  ddx_c1$take_din;
    reg  ddx_c1$take_next;
    reg  [35:0] ddx_c1$din;
    wire  [35:0] ddx_c1$head;
    reg  ddx_c2$clock;
    reg  ddx_c2$we;
    reg  [1:0] ddx_c2$wr;
    reg  [1:0] ddx_c2$rd;
    reg  ddx_c2$take_din;
    reg  ddx_c2$take_next;
    reg  [35:0] ddx_c2$din;
    wire  [35:0] ddx_c2$head;
    
    // Local signals
    reg  [2:0] count_next;
    reg  push;
    reg  pop;
    reg  take_din;
    reg  take_next;
    
    // Sub module instances
    raster_top$fragments$core$fifo$count count(
        .d(count$d),
        .q(count$q),
        .clock(count$clock)
    );
    raster_top$fragments$core$fifo$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    raster_top$fragments$core$fifo$held held(
        .d(held$d),
        .q(held$q),
        .clock(held$clock)
    );
    raster_top$fragments$core$fifo$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    raster_top$fragments$core$fifo$wr wr(
        .d(wr$d),
        .q(wr$q),
        .clock(wr$clock)
    );
    raster_top$fragments$core$fifo$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    raster_top$fragments$core$fifo$y y(
        .clock(y$clock),
        .we(y$we),
        .wr(y$wr),
        .rd(y$rd),
        .take_din(y$take_din),
        .take_next(y$take_next),
        .din(y$din),
        .head(y$head)
    );
    raster_top$fragments$core$fifo$xl xl(
        .clock(xl$clock),
        .we(xl$we),
        .wr(xl$wr),
        .rd(xl$rd),
        .take_din(xl$take_din),
        .take_next(xl$take_next),
        .din(xl$din),
        .head(xl$head)
    );
    raster_top$fragments$core$fifo$xr xr(
        .clock(xr$clock),
        .we(xr$we),
        .wr(xr$wr),
        .rd(xr$rd),
        .take_din(xr$take_din),
        .take_next(xr$take_next),
        .din(xr$din),
        .head(xr$head)
    );
    raster_top$fragments$core$fifo$left_z left_z(
        .clock(left_z$clock),
        .we(left_z$we),
        .wr(left_z$wr),
        .rd(left_z$rd),
        .take_din(left_z$take_din),
        .take_next(left_z$take_next),
        .din(left_z$din),
        .head(left_z$head)
    );
    raster_top$fragments$core$fifo$left_c0 left_c0(
        .clock(left_c0$clock),
        .we(left_c0$we),
        .wr(left_c0$wr),
        .rd(left_c0$rd),
        .take_din(left_c0$take_din),
        .take_next(left_c0$take_next),
        .din(left_c0$din),
        .head(left_c0$head)
    );
    raster_top$fragments$core$fifo$left_c1 left_c1(
        .clock(left_c1$clock),
        .we(left_c1$we),
        .wr(left_c1$wr),
        .rd(left_c1$rd),
        .take_din(left_c1$take_din),
        .take_next(left_c1$take_next),
        .din(left_c1$din),
        .head(left_c1$head)
    );
    raster_top$fragments$core$fifo$left_c2 left_c2(
        .clock(left_c2$clock),
        .we(left_c2$we),
        .wr(left_c2$wr),
        .rd(left_c2$rd),
        .take_din(left_c2$take_din),
        .take_next(left_c2$take_next),
        .din(left_c2$din),
        .head(left_c2$head)
    );
    raster_top$fragments$core$fifo$right_z right_z(
        .clock(right_z$clock),
        .we(right_z$we),
        .wr(right_z$wr),
        .rd(right_z$rd),
        .take_din(right_z$take_din),
        .take_next(right_z$take_next),
        .din(right_z$din),
        .head(right_z$head)
    );
    raster_top$fragments$core$fifo$right_c0 right_c0(
        .clock(right_c0$clock),
        .we(right_c0$we),
        .wr(right_c0$wr),
        .rd(right_c0$rd),
        .take_din(right_c0$take_din),
        .take_next(right_c0$take_next),
        .din(right_c0$din),
        .head(right_c0$head)
    );
    raster_top$fragments$core$fifo$right_c1 right_c1(
        .clock(right_c1$clock),
        .we(right_c1$we),
        .wr(right_c1$wr),
        .rd(right_c1$rd),
        .take_din(right_c1$take_din),
        .take_next(right_c1$take_next),
        .din(right_c1$din),
        .head(right_c1$head)
    );
    raster_top$fragments$core$fifo$right_c2 right_c2(
        .clock(right_c2$clock),
        .we(right_c2$we),
        .wr(right_c2$wr),
        .rd(right_c2$rd),
        .take_din(right_c2$take_din),
        .take_next(right_c2$take_next),
        .din(right_c2$din),
        .head(right_c2$head)
    );
    raster_top$fragments$core$fifo$ddx_z ddx_z(
        .clock(ddx_z$clock),
        .we(ddx_z$we),
        .wr(ddx_z$wr),
        .rd(ddx_z$rd),
        .take_din(ddx_z$take_din),
        .take_next(ddx_z$take_next),
        .din(ddx_z$din),
        .head(ddx_z$head)
    );
    raster_top$fragments$core$fifo$ddx_c0 ddx_c0(
        .clock(ddx_c0$clock),
        .we(ddx_c0$we),
        .wr(ddx_c0$wr),
        .rd(ddx_c0$rd),
        .take_din(ddx_c0$take_din),
        .take_next(ddx_c0$take_next),
        .din(ddx_c0$din),
        .head(ddx_c0$head)
    );
    raster_top$fragments$core$fifo$ddx_c1 ddx_c1(
        .clock(ddx_c1$clock),
        .we(ddx_c1$we),
        .wr(ddx_c1$wr),
        .rd(ddx_c1$rd),
        .take_din(ddx_c1$take_din),
        .take_next(ddx_c1$take_next),
        .din(ddx_c1$din),
        .head(ddx_c1$head)
    );
    raster_top$fragments$core$fifo$ddx_c2 ddx_c2(
        .clock(ddx_c2$clock),
        .we(ddx_c2$we),
        .wr(ddx_c2$wr),
        .rd(ddx_c2$rd),
        .take_din(ddx_c2$take_din),
        .take_next(ddx_c2$take_next),
        .din(ddx_c2$din),
        .head(ddx_c2$head)
    );
    
    // Update code
    always @(*) begin
        count$clock = clock;
        full$clock = clock;
        held$clock = clock;
        one$clock = clock;
        wr$clock = clock;
        rd$clock = clock;
        count$d = count$q;
        full$d = full$q;
        held$d = held$q;
        one$d = one$q;
        wr$d = wr$q;
        rd$d = rd$q;
        inp$ready = ~full$q;
        out$valid = held$q;
        empty = ~held$q;
        push = inp$valid & ~full$q;
        pop = held$q & out$ready;
        take_din = ~held$q | (one$q & out$ready);
        take_next = pop & ~one$q;
        if (push) begin
            wr$d = wr$q + 32'h1;
        end
        if (pop) begin
            rd$d = rd$q + 32'h1;
        end
        count_next = count$q;
        if (push & ~pop) begin
            count_next = count$q + 32'h1;
        end
        if (pop & ~push) begin
            count_next = count$q - 32'h1;
        end
        count$d = count_next;
        full$d = count_next == depth;
        held$d = count_next != 32'h0;
        one$d = count_next == 32'h1;
        y$clock = clock;
        y$we = push;
        y$wr = wr$q;
        y$rd = rd$q;
        y$take_din = take_din;
        y$take_next = take_next;
        y$din = inp$y;
        out$y = y$head;
        xl$clock = clock;
        xl$we = push;
        xl$wr = wr$q;
        xl$rd = rd$q;
        xl$take_din = take_din;
        xl$take_next = take_next;
        xl$din = inp$xl;
        out$xl = xl$head;
        xr$clock = clock;
        xr$we = push;
        xr$wr = wr$q;
        xr$rd = rd$q;
        xr$take_din = take_din;
        xr$take_next = take_next;
        xr$din = inp$xr;
        out$xr = xr$head;
        left_z$clock = clock;
        left_z$we = push;
        left_z$wr = wr$q;
        left_z$rd = rd$q;
        left_z$take_din = take_din;
        left_z$take_next = take_next;
        left_z$din = inp$left_z;
        out$left_z = left_z$head;
        left_c0$clock = clock;
        left_c0$we = push;
        left_c0$wr = wr$q;
        left_c0$rd = rd$q;
        left_c0$take_din = take_din;
        left_c0$take_next = take_next;
        left_c0$din = inp$left_c0;
        out$left_c0 = left_c0$head;
        left_c1$clock = clock;
        left_c1$we = push;
        left_c1$wr = wr$q;
        left_c1$rd = rd$q;
        left_c1$take_din = take_din;
        left_c1$take_next = take_next;
        left_c1$din = inp$left_c1;
        out$left_c1 = left_c1$head;
        left_c2$clock = clock;
        left_c2$we = push;
        left_c2$wr = wr$q;
        left_c2$rd = rd$q;
        left_c2$take_din = take_din;
        left_c2$take_next = take_next;
        left_c2$din = inp$left_c2;
        out$left_c2 = left_c2$head;
        right_z$clock = clock;
        right_z$we = push;
        right_z$wr = wr$q;
        right_z$rd = rd$q;
        right_z$take_din = take_din;
        right_z$take_next = take_next;
        right_z$din = inp$right_z;
        out$right_z = right_z$head;
        right_c0$clock = clock;
        right_c0$we = push;
        right_c0$wr = wr$q;
        right_c0$rd = rd$q;
        right_c0$take_din = take_din;
        right_c0$take_next = take_next;
        right_c0$din = inp$right_c0;
        out$right_c0 = right_c0$head;
        right_c1$clock = clock;
        right_c1$we = push;
        right_c1$wr = wr$q;
        right_c1$rd = rd$q;
        right_c1$take_din = take_din;
        right_c1$take_next = take_next;
        right_c1$din = inp$right_c1;
        out$right_c1 = right_c1$head;
        right_c2$clock = clock;
        right_c2$we = push;
        right_c2$wr = wr$q;
        right_c2$rd = rd$q;
        right_c2$take_din = take_din;
        right_c2$take_next = take_next;
        right_c2$din = inp$right_c2;
        out$right_c2 = right_c2$head;
        ddx_z$clock = clock;
        ddx_z$we = push;
        ddx_z$wr = wr$q;
        ddx_z$rd = rd$q;
        ddx_z$take_din = take_din;
        ddx_z$take_next = take_next;
        ddx_z$din = inp$ddx_z;
        out$ddx_z = ddx_z$head;
        ddx_c0$clock = clock;
        ddx_c0$we = push;
        ddx_c0$wr = wr$q;
        ddx_c0$rd = rd$q;
        ddx_c0$take_din = take_din;
        ddx_c0$take_next = take_next;
        ddx_c0$din = inp$ddx_c0;
        out$ddx_c0 = ddx_c0$head;
        ddx_c1$clock = clock;
        ddx_c1$we = push;
        ddx_c1$wr = wr$q;
        ddx_c1$rd = rd$q;
        ddx_c1$take_din = take_din;
        ddx_c1$take_next = take_next;
        ddx_c1$din = inp$ddx_c1;
        out$ddx_c1 = ddx_c1$head;
        ddx_c2$clock = clock;
        ddx_c2$we = push;
        ddx_c2$wr = wr$q;
        ddx_c2$rd = rd$q;
        ddx_c2$take_din = take_din;
        ddx_c2$take_next = take_next;
        ddx_c2$din = inp$ddx_c2;
        out$ddx_c2 = ddx_c2$head;
    end
    
endmodule // raster_top$fragments$core$fifo


module raster_top$fragments$core$fifo$count(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$count


module raster_top$fragments$core$fifo$ddx_c0(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [35:0] din;
    output reg  [35:0] head;
    
    // Stub signals
    reg  [35:0] e$0$d;
    wire  [35:0] e$0$q;
    reg  e$0$clock;
    reg  [35:0] e$1$d;
    wire  [35:0] e$1$q;
    reg  e$1$clock;
    reg  [35:0] e$2$d;
    wire  [35:0] e$2$q;
    reg  e$2$clock;
    reg  [35:0] e$3$d;
    wire  [35:0] e$3$q;
    reg  e$3$clock;
    reg  [35:0] h$d;
    wire  [35:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$ddx_c0$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$ddx_c0$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$ddx_c0$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$ddx_c0$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$ddx_c0$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$ddx_c0


module raster_top$fragments$core$fifo$ddx_c0$e$0(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c0$e$0


module raster_top$fragments$core$fifo$ddx_c0$e$1(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c0$e$1


module raster_top$fragments$core$fifo$ddx_c0$e$2(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c0$e$2


module raster_top$fragments$core$fifo$ddx_c0$e$3(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c0$e$3


module raster_top$fragments$core$fifo$ddx_c0$h(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c0$h


module raster_top$fragments$core$fifo$ddx_c1(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [35:0] din;
    output reg  [35:0] head;
    
    // Stub signals
    reg  [35:0] e$0$d;
    wire  [35:0] e$0$q;
    reg  e$0$clock;
    reg  [35:0] e$1$d;
    wire  [35:0] e$1$q;
    reg  e$1$clock;
    reg  [35:0] e$2$d;
    wire  [35:0] e$2$q;
    reg  e$2$clock;
    reg  [35:0] e$3$d;
    wire  [35:0] e$3$q;
    reg  e$3$clock;
    reg  [35:0] h$d;
    wire  [35:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$ddx_c1$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$ddx_c1$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$ddx_c1$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$ddx_c1$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$ddx_c1$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$ddx_c1


module raster_top$fragments$core$fifo$ddx_c1$e$0(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c1$e$0


module raster_top$fragments$core$fifo$ddx_c1$e$1(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c1$e$1


module raster_top$fragments$core$fifo$ddx_c1$e$2(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c1$e$2


module raster_top$fragments$core$fifo$ddx_c1$e$3(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c1$e$3


module raster_top$fragments$core$fifo$ddx_c1$h(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c1$h


module raster_top$fragments$core$fifo$ddx_c2(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [35:0] din;
    output reg  [35:0] head;
    
    // Stub signals
    reg  [35:0] e$0$d;
    wire  [35:0] e$0$q;
    reg  e$0$clock;
    reg  [35:0] e$1$d;
    wire  [35:0] e$1$q;
    reg  e$1$clock;
    reg  [35:0] e$2$d;
    wire  [35:0] e$2$q;
    reg  e$2$clock;
    reg  [35:0] e$3$d;
    wire  [35:0] e$3$q;
    reg  e$3$clock;
    reg  [35:0] h$d;
    wire  [35:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$ddx_c2$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$ddx_c2$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$ddx_c2$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$ddx_c2$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$ddx_c2$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$ddx_c2


module raster_top$fragments$core$fifo$ddx_c2$e$0(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c2$e$0


module raster_top$fragments$core$fifo$ddx_c2$e$1(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c2$e$1


module raster_top$fragments$core$fifo$ddx_c2$e$2(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c2$e$2


module raster_top$fragments$core$fifo$ddx_c2$e$3(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c2$e$3


module raster_top$fragments$core$fifo$ddx_c2$h(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_c2$h


module raster_top$fragments$core$fifo$ddx_z(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [39:0] din;
    output reg  [39:0] head;
    
    // Stub signals
    reg  [39:0] e$0$d;
    wire  [39:0] e$0$q;
    reg  e$0$clock;
    reg  [39:0] e$1$d;
    wire  [39:0] e$1$q;
    reg  e$1$clock;
    reg  [39:0] e$2$d;
    wire  [39:0] e$2$q;
    reg  e$2$clock;
    reg  [39:0] e$3$d;
    wire  [39:0] e$3$q;
    reg  e$3$clock;
    reg  [39:0] h$d;
    wire  [39:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$ddx_z$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$ddx_z$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$ddx_z$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$ddx_z$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$ddx_z$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$ddx_z


module raster_top$fragments$core$fifo$ddx_z$e$0(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_z$e$0


module raster_top$fragments$core$fifo$ddx_z$e$1(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_z$e$1


module raster_top$fragments$core$fifo$ddx_z$e$2(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_z$e$2


module raster_top$fragments$core$fifo$ddx_z$e$3(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_z$e$3


module raster_top$fragments$core$fifo$ddx_z$h(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$ddx_z$h


module raster_top$fragments$core$fifo$full(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$full


module raster_top$fragments$core$fifo$held(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$held


module raster_top$fragments$core$fifo$left_c0(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [31:0] din;
    output reg  [31:0] head;
    
    // Stub signals
    reg  [31:0] e$0$d;
    wire  [31:0] e$0$q;
    reg  e$0$clock;
    reg  [31:0] e$1$d;
    wire  [31:0] e$1$q;
    reg  e$1$clock;
    reg  [31:0] e$2$d;
    wire  [31:0] e$2$q;
    reg  e$2$clock;
    reg  [31:0] e$3$d;
    wire  [31:0] e$3$q;
    reg  e$3$clock;
    reg  [31:0] h$d;
    wire  [31:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$left_c0$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$left_c0$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$left_c0$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$left_c0$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$left_c0$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$left_c0


module raster_top$fragments$core$fifo$left_c0$e$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c0$e$0


module raster_top$fragments$core$fifo$left_c0$e$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c0$e$1


module raster_top$fragments$core$fifo$left_c0$e$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c0$e$2


module raster_top$fragments$core$fifo$left_c0$e$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c0$e$3


module raster_top$fragments$core$fifo$left_c0$h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c0$h


module raster_top$fragments$core$fifo$left_c1(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [31:0] din;
    output reg  [31:0] head;
    
    // Stub signals
    reg  [31:0] e$0$d;
    wire  [31:0] e$0$q;
    reg  e$0$clock;
    reg  [31:0] e$1$d;
    wire  [31:0] e$1$q;
    reg  e$1$clock;
    reg  [31:0] e$2$d;
    wire  [31:0] e$2$q;
    reg  e$2$clock;
    reg  [31:0] e$3$d;
    wire  [31:0] e$3$q;
    reg  e$3$clock;
    reg  [31:0] h$d;
    wire  [31:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$left_c1$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$left_c1$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$left_c1$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$left_c1$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$left_c1$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$left_c1


module raster_top$fragments$core$fifo$left_c1$e$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c1$e$0


module raster_top$fragments$core$fifo$left_c1$e$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c1$e$1


module raster_top$fragments$core$fifo$left_c1$e$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c1$e$2


module raster_top$fragments$core$fifo$left_c1$e$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c1$e$3


module raster_top$fragments$core$fifo$left_c1$h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c1$h


module raster_top$fragments$core$fifo$left_c2(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [31:0] din;
    output reg  [31:0] head;
    
    // Stub signals
    reg  [31:0] e$0$d;
    wire  [31:0] e$0$q;
    reg  e$0$clock;
    reg  [31:0] e$1$d;
    wire  [31:0] e$1$q;
    reg  e$1$clock;
    reg  [31:0] e$2$d;
    wire  [31:0] e$2$q;
    reg  e$2$clock;
    reg  [31:0] e$3$d;
    wire  [31:0] e$3$q;
    reg  e$3$clock;
    reg  [31:0] h$d;
    wire  [31:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$left_c2$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$left_c2$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$left_c2$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$left_c2$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$left_c2$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$left_c2


module raster_top$fragments$core$fifo$left_c2$e$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c2$e$0


module raster_top$fragments$core$fifo$left_c2$e$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c2$e$1


module raster_top$fragments$core$fifo$left_c2$e$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c2$e$2


module raster_top$fragments$core$fifo$left_c2$e$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c2$e$3


module raster_top$fragments$core$fifo$left_c2$h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_c2$h


module raster_top$fragments$core$fifo$left_z(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [35:0] din;
    output reg  [35:0] head;
    
    // Stub signals
    reg  [35:0] e$0$d;
    wire  [35:0] e$0$q;
    reg  e$0$clock;
    reg  [35:0] e$1$d;
    wire  [35:0] e$1$q;
    reg  e$1$clock;
    reg  [35:0] e$2$d;
    wire  [35:0] e$2$q;
    reg  e$2$clock;
    reg  [35:0] e$3$d;
    wire  [35:0] e$3$q;
    reg  e$3$clock;
    reg  [35:0] h$d;
    wire  [35:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$left_z$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$left_z$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$left_z$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$left_z$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$left_z$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$left_z


module raster_top$fragments$core$fifo$left_z$e$0(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_z$e$0


module raster_top$fragments$core$fifo$left_z$e$1(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_z$e$1


module raster_top$fragments$core$fifo$left_z$e$2(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_z$e$2


module raster_top$fragments$core$fifo$left_z$e$3(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_z$e$3


module raster_top$fragments$core$fifo$left_z$h(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$left_z$h


module raster_top$fragments$core$fifo$one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$one


module raster_top$fragments$core$fifo$rd(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$rd


module raster_top$fragments$core$fifo$right_c0(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [31:0] din;
    output reg  [31:0] head;
    
    // Stub signals
    reg  [31:0] e$0$d;
    wire  [31:0] e$0$q;
    reg  e$0$clock;
    reg  [31:0] e$1$d;
    wire  [31:0] e$1$q;
    reg  e$1$clock;
    reg  [31:0] e$2$d;
    wire  [31:0] e$2$q;
    reg  e$2$clock;
    reg  [31:0] e$3$d;
    wire  [31:0] e$3$q;
    reg  e$3$clock;
    reg  [31:0] h$d;
    wire  [31:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$right_c0$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$right_c0$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$right_c0$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$right_c0$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$right_c0$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$right_c0


module raster_top$fragments$core$fifo$right_c0$e$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c0$e$0


module raster_top$fragments$core$fifo$right_c0$e$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c0$e$1


module raster_top$fragments$core$fifo$right_c0$e$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c0$e$2


module raster_top$fragments$core$fifo$right_c0$e$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c0$e$3


module raster_top$fragments$core$fifo$right_c0$h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c0$h


module raster_top$fragments$core$fifo$right_c1(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [31:0] din;
    output reg  [31:0] head;
    
    // Stub signals
    reg  [31:0] e$0$d;
    wire  [31:0] e$0$q;
    reg  e$0$clock;
    reg  [31:0] e$1$d;
    wire  [31:0] e$1$q;
    reg  e$1$clock;
    reg  [31:0] e$2$d;
    wire  [31:0] e$2$q;
    reg  e$2$clock;
    reg  [31:0] e$3$d;
    wire  [31:0] e$3$q;
    reg  e$3$clock;
    reg  [31:0] h$d;
    wire  [31:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$right_c1$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$right_c1$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$right_c1$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$right_c1$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$right_c1$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$right_c1


module raster_top$fragments$core$fifo$right_c1$e$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c1$e$0


module raster_top$fragments$core$fifo$right_c1$e$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c1$e$1


module raster_top$fragments$core$fifo$right_c1$e$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c1$e$2


module raster_top$fragments$core$fifo$right_c1$e$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c1$e$3


module raster_top$fragments$core$fifo$right_c1$h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c1$h


module raster_top$fragments$core$fifo$right_c2(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [31:0] din;
    output reg  [31:0] head;
    
    // Stub signals
    reg  [31:0] e$0$d;
    wire  [31:0] e$0$q;
    reg  e$0$clock;
    reg  [31:0] e$1$d;
    wire  [31:0] e$1$q;
    reg  e$1$clock;
    reg  [31:0] e$2$d;
    wire  [31:0] e$2$q;
    reg  e$2$clock;
    reg  [31:0] e$3$d;
    wire  [31:0] e$3$q;
    reg  e$3$clock;
    reg  [31:0] h$d;
    wire  [31:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$right_c2$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$right_c2$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$right_c2$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$right_c2$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$right_c2$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$right_c2


module raster_top$fragments$core$fifo$right_c2$e$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c2$e$0


module raster_top$fragments$core$fifo$right_c2$e$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c2$e$1


module raster_top$fragments$core$fifo$right_c2$e$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c2$e$2


module raster_top$fragments$core$fifo$right_c2$e$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c2$e$3


module raster_top$fragments$core$fifo$right_c2$h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_c2$h


module raster_top$fragments$core$fifo$right_z(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [35:0] din;
    output reg  [35:0] head;
    
    // Stub signals
    reg  [35:0] e$0$d;
    wire  [35:0] e$0$q;
    reg  e$0$clock;
    reg  [35:0] e$1$d;
    wire  [35:0] e$1$q;
    reg  e$1$clock;
    reg  [35:0] e$2$d;
    wire  [35:0] e$2$q;
    reg  e$2$clock;
    reg  [35:0] e$3$d;
    wire  [35:0] e$3$q;
    reg  e$3$clock;
    reg  [35:0] h$d;
    wire  [35:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$right_z$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$right_z$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$right_z$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$right_z$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$right_z$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$right_z


module raster_top$fragments$core$fifo$right_z$e$0(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_z$e$0


module raster_top$fragments$core$fifo$right_z$e$1(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_z$e$1


module raster_top$fragments$core$fifo$right_z$e$2(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_z$e$2


module raster_top$fragments$core$fifo$right_z$e$3(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_z$e$3


module raster_top$fragments$core$fifo$right_z$h(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$right_z$h


module raster_top$fragments$core$fifo$wr(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$wr


module raster_top$fragments$core$fifo$xl(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [12:0] din;
    output reg  [12:0] head;
    
    // Stub signals
    reg  [12:0] e$0$d;
    wire  [12:0] e$0$q;
    reg  e$0$clock;
    reg  [12:0] e$1$d;
    wire  [12:0] e$1$q;
    reg  e$1$clock;
    reg  [12:0] e$2$d;
    wire  [12:0] e$2$q;
    reg  e$2$clock;
    reg  [12:0] e$3$d;
    wire  [12:0] e$3$q;
    reg  e$3$clock;
    reg  [12:0] h$d;
    wire  [12:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$xl$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$xl$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$xl$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$xl$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$xl$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$xl


module raster_top$fragments$core$fifo$xl$e$0(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xl$e$0


module raster_top$fragments$core$fifo$xl$e$1(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xl$e$1


module raster_top$fragments$core$fifo$xl$e$2(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xl$e$2


module raster_top$fragments$core$fifo$xl$e$3(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xl$e$3


module raster_top$fragments$core$fifo$xl$h(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xl$h


module raster_top$fragments$core$fifo$xr(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [12:0] din;
    output reg  [12:0] head;
    
    // Stub signals
    reg  [12:0] e$0$d;
    wire  [12:0] e$0$q;
    reg  e$0$clock;
    reg  [12:0] e$1$d;
    wire  [12:0] e$1$q;
    reg  e$1$clock;
    reg  [12:0] e$2$d;
    wire  [12:0] e$2$q;
    reg  e$2$clock;
    reg  [12:0] e$3$d;
    wire  [12:0] e$3$q;
    reg  e$3$clock;
    reg  [12:0] h$d;
    wire  [12:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$xr$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$xr$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$xr$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$xr$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$xr$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$xr


module raster_top$fragments$core$fifo$xr$e$0(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xr$e$0


module raster_top$fragments$core$fifo$xr$e$1(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xr$e$1


module raster_top$fragments$core$fifo$xr$e$2(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xr$e$2


module raster_top$fragments$core$fifo$xr$e$3(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xr$e$3


module raster_top$fragments$core$fifo$xr$h(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$xr$h


module raster_top$fragments$core$fifo$y(clock,we,wr,rd,take_din,take_next,din,head);
    
    // Module arguments
    input wire  clock;
    input wire  we;
    input wire  [1:0] wr;
    input wire  [1:0] rd;
    input wire  take_din;
    input wire  take_next;
    input wire  [9:0] din;
    output reg  [9:0] head;
    
    // Stub signals
    reg  [9:0] e$0$d;
    wire  [9:0] e$0$q;
    reg  e$0$clock;
    reg  [9:0] e$1$d;
    wire  [9:0] e$1$q;
    reg  e$1$clock;
    reg  [9:0] e$2$d;
    wire  [9:0] e$2$q;
    reg  e$2$clock;
    reg  [9:0] e$3$d;
    wire  [9:0] e$3$q;
    reg  e$3$clock;
    reg  [9:0] h$d;
    wire  [9:0] h$q;
    reg  h$clock;
    
    // Local signals
    reg  [1:0] behind;
    
    // Sub module instances
    raster_top$fragments$core$fifo$y$e$0 e$0(
        .d(e$0$d),
        .q(e$0$q),
        .clock(e$0$clock)
    );
    raster_top$fragments$core$fifo$y$e$1 e$1(
        .d(e$1$d),
        .q(e$1$q),
        .clock(e$1$clock)
    );
    raster_top$fragments$core$fifo$y$e$2 e$2(
        .d(e$2$d),
        .q(e$2$q),
        .clock(e$2$clock)
    );
    raster_top$fragments$core$fifo$y$e$3 e$3(
        .d(e$3$d),
        .q(e$3$q),
        .clock(e$3$clock)
    );
    raster_top$fragments$core$fifo$y$h h(
        .d(h$d),
        .q(h$q),
        .clock(h$clock)
    );
    
    // Update code
    always @(*) begin
        e$0$clock = clock;
        e$0$d = e$0$q;
        if ((wr == 0) & we) begin
            e$0$d = din;
        end
        e$1$clock = clock;
        e$1$d = e$1$q;
        if ((wr == 1) & we) begin
            e$1$d = din;
        end
        e$2$clock = clock;
        e$2$d = e$2$q;
        if ((wr == 2) & we) begin
            e$2$d = din;
        end
        e$3$clock = clock;
        e$3$d = e$3$q;
        if ((wr == 3) & we) begin
            e$3$d = din;
        end
        behind = rd + 32'h1;
        h$clock = clock;
        h$d = h$q;
        if (take_next) begin
            h$d = e$0$q;
            if (behind == 1) begin
                h$d = e$1$q;
            end
            if (behind == 2) begin
                h$d = e$2$q;
            end
            if (behind == 3) begin
                h$d = e$3$q;
            end
        end
        if (take_din) begin
            h$d = din;
        end
        head = h$q;
    end
    
endmodule // raster_top$fragments$core$fifo$y


module raster_top$fragments$core$fifo$y$e$0(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$y$e$0


module raster_top$fragments$core$fifo$y$e$1(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$y$e$1


module raster_top$fragments$core$fifo$y$e$2(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$y$e$2


module raster_top$fragments$core$fifo$y$e$3(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$y$e$3


module raster_top$fragments$core$fifo$y$h(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$fifo$y$h


module raster_top$fragments$core$last_in(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$last_in


module raster_top$fragments$core$span(clock,width,inp$valid,inp$ready,inp$y,inp$xl,inp$xr,inp$left_z,inp$left_c0,inp$left_c1,inp$left_c2,inp$right_z,inp$right_c0,inp$right_c1,inp$right_c2,inp$ddx_z,inp$ddx_c0,inp$ddx_c1,inp$ddx_c2,out$valid,out$ready,out$x,out$y,out$z,out$rgb0,out$rgb1,out$rgb2,idle);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$y;
    input wire  [12:0] inp$xl;
    input wire  [12:0] inp$xr;
    input wire  [35:0] inp$left_z;
    input wire  [31:0] inp$left_c0;
    input wire  [31:0] inp$left_c1;
    input wire  [31:0] inp$left_c2;
    input wire  [35:0] inp$right_z;
    input wire  [31:0] inp$right_c0;
    input wire  [31:0] inp$right_c1;
    input wire  [31:0] inp$right_c2;
    input wire  [39:0] inp$ddx_z;
    input wire  [35:0] inp$ddx_c0;
    input wire  [35:0] inp$ddx_c1;
    input wire  [35:0] inp$ddx_c2;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [9:0] out$x;
    output reg  [9:0] out$y;
    output reg  [15:0] out$z;
    output reg  [7:0] out$rgb0;
    output reg  [7:0] out$rgb1;
    output reg  [7:0] out$rgb2;
    output reg  idle;
    
    // Stub signals
    wire  clip_x$on;
    wire  clip_z$on;
    reg  busy$d;
    wire  busy$q;
    reg  busy$clock;
    reg  drop$d;
    wire  drop$q;
    reg  drop$clock;
    reg  left$d;
    wire  left$q;
    reg  left$clock;
    reg  [12:0] x$d;
    wire  [12:0] x$q;
    reg  x$clock;
    reg  [12:0] last$d;
    wire  [12:0] last$q;
    reg  last$clock;
    reg  at_last$d;
    wire  at_last$q;
    reg  at_last$clock;
    reg  [9:0] y$d;
    wire  [9:0] y$q;
    reg  y$clock;
    reg  [35:0] a_z$d;
    wire  [35:0] a_z$q;
    reg  a_z$clock;
    reg  [31:0] a_c0$d;
    wire  [31:0] a_c0$q;
    reg  a_c0$clock;
    reg  [31:0] a_c1$d;
    wire  [31:0] a_c1$q;
    reg  a_c1$clock;
    reg  [31:0] a_c2$d;
    wire  [31:0] a_c2$q;
    reg  a_c2$clock;
    reg  [35:0] d_z$d;
    wire  [35:0] d_z$q;
    reg  d_z$clock;
    reg  [31:0] d_c0$d;
    wire  [31:0] d_c0$q;
    reg  d_c0$clock;
    reg  [31:0] d_c1$d;
    wire  [31:0] d_c1$q;
    reg  d_c1$clock;
    reg  [31:0] d_c2$d;
    wire  [31:0] d_c2$q;
    reg  d_c2$clock;
    reg  [35:0] zl$x;
    wire  zl$neg;
    wire  zl$over;
    reg  [35:0] zr$x;
    wire  zr$neg;
    wire  zr$over;
    reg  [12:0] xl_neg$x;
    wire  xl_neg$neg;
    reg  [12:0] xr_neg$x;
    wire  xr_neg$neg;
    reg  [35:0] zp$x;
    wire  zp$neg;
    wire  zp$over;
    wire  [15:0] zp$low;
    reg  [31:0] c0$x;
    wire  c0$neg;
    wire  c0$over;
    wire  [7:0] c0$low;
    reg  [31:0] c1$x;
    wire  c1$neg;
    wire  c1$over;
    wire  [7:0] c1$low;
    reg  [31:0] c2$x;
    wire  c2$neg;
    wire  c2$over;
    wire  [7:0] c2$low;
    reg  [12:0] xl_on$a;
    reg  [12:0] xl_on$b;
    wire  xl_on$lt;
    reg  o_valid$d;
    wire  o_valid$q;
    reg  o_valid$clock;
    reg  [9:0] o_x$d;
    wire  [9:0] o_x$q;
    reg  o_x$clock;
    reg  [9:0] o_y$d;
    wire  [9:0] o_y$q;
    reg  o_y$clock;
    reg  [15:0] o_z$d;
    wire  [15:0] o_z$q;
    reg  o_z$clock;
    reg  [7:0] o_rgb0$d;
    wire  [7:0] o_rgb0$q;
    reg  o_rgb0$clock;
    reg  [7:0] o_rgb1$d;
    wire  [7:0] o_rgb1$q;
    reg  o_rgb1$clock;
    reg  [7:0] o_rgb2$d;
    wire  [7:0] o_rgb2$q;
    reg  o_rgb2$clock;
    
    // Local signals
    reg  [12:0] x_next;
    reg  [12:0] x_first;
    reg  [12:0] x_last;
    reg  one_pixel;
    reg  xr_off;
    reg  [12:0] last_column;
    reg  dropped;
    reg  ends;
    reg  [12:0] width_x;
    reg  valid;
    reg  [7:0] rgb0;
    reg  [7:0] rgb1;
    reg  [7:0] rgb2;
    reg  advance;
    reg  ready;
    reg  accept;
    
    // Sub module instances
    raster_top$fragments$core$span$clip_x clip_x(
        .on(clip_x$on)
    );
    raster_top$fragments$core$span$clip_z clip_z(
        .on(clip_z$on)
    );
    raster_top$fragments$core$span$busy busy(
        .d(busy$d),
        .q(busy$q),
        .clock(busy$clock)
    );
    raster_top$fragments$core$span$drop drop(
        .d(drop$d),
        .q(drop$q),
        .clock(drop$clock)
    );
    raster_top$fragments$core$span$left left(
        .d(left$d),
        .q(left$q),
        .clock(left$clock)
    );
    raster_top$fragments$core$span$x x(
        .d(x$d),
        .q(x$q),
        .clock(x$clock)
    );
    raster_top$fragments$core$span$last last(
        .d(last$d),
        .q(last$q),
        .clock(last$clock)
    );
    raster_top$fragments$core$span$at_last at_last(
        .d(at_last$d),
        .q(at_last$q),
        .clock(at_last$clock)
    );
    raster_top$fragments$core$span$y y(
        .d(y$d),
        .q(y$q),
        .clock(y$clock)
    );
    raster_top$fragments$core$span$a_z a_z(
        .d(a_z$d),
        .q(a_z$q),
        .clock(a_z$clock)
    );
    raster_top$fragments$core$span$a_c0 a_c0(
        .d(a_c0$d),
        .q(a_c0$q),
        .clock(a_c0$clock)
    );
    raster_top$fragments$core$span$a_c1 a_c1(
        .d(a_c1$d),
        .q(a_c1$q),
        .clock(a_c1$clock)
    );
    raster_top$fragments$core$span$a_c2 a_c2(
        .d(a_c2$d),
        .q(a_c2$q),
        .clock(a_c2$clock)
    );
    raster_top$fragments$core$span$d_z d_z(
        .d(d_z$d),
        .q(d_z$q),
        .clock(d_z$clock)
    );
    raster_top$fragments$core$span$d_c0 d_c0(
        .d(d_c0$d),
        .q(d_c0$q),
        .clock(d_c0$clock)
    );
    raster_top$fragments$core$span$d_c1 d_c1(
        .d(d_c1$d),
        .q(d_c1$q),
        .clock(d_c1$clock)
    );
    raster_top$fragments$core$span$d_c2 d_c2(
        .d(d_c2$d),
        .q(d_c2$q),
        .clock(d_c2$clock)
    );
    raster_top$fragments$core$span$zl zl(
        .x(zl$x),
        .neg(zl$neg),
        .over(zl$over)
    );
    raster_top$fragments$core$span$zr zr(
        .x(zr$x),
        .neg(zr$neg),
        .over(zr$over)
    );
    raster_top$fragments$core$span$xl_neg xl_neg(
        .x(xl_neg$x),
        .neg(xl_neg$neg)
    );
    raster_top$fragments$core$span$xr_neg xr_neg(
        .x(xr_neg$x),
        .neg(xr_neg$neg)
    );
    raster_top$fragments$core$span$zp zp(
        .x(zp$x),
        .neg(zp$neg),
        .over(zp$over),
        .low(zp$low)
    );
    raster_top$fragments$core$span$c0 c0(
        .x(c0$x),
        .neg(c0$neg),
        .over(c0$over),
        .low(c0$low)
    );
    raster_top$fragments$core$span$c1 c1(
        .x(c1$x),
        .neg(c1$neg),
        .over(c1$over),
        .low(c1$low)
    );
    raster_top$fragments$core$span$c2 c2(
        .x(c2$x),
        .neg(c2$neg),
        .over(c2$over),
        .low(c2$low)
    );
    raster_top$fragments$core$span$xl_on xl_on(
        .a(xl_on$a),
        .b(xl_on$b),
        .lt(xl_on$lt)
    );
    raster_top$fragments$core$span$o_valid o_valid(
        .d(o_valid$d),
        .q(o_valid$q),
        .clock(o_valid$clock)
    );
    raster_top$fragments$core$span$o_x o_x(
        .d(o_x$d),
        .q(o_x$q),
        .clock(o_x$clock)
    );
    raster_top$fragments$core$span$o_y o_y(
        .d(o_y$d),
        .q(o_y$q),
        .clock(o_y$clock)
    );
    raster_top$fragments$core$span$o_z o_z(
        .d(o_z$d),
        .q(o_z$q),
        .clock(o_z$clock)
    );
    raster_top$fragments$core$span$o_rgb0 o_rgb0(
        .d(o_rgb0$d),
        .q(o_rgb0$q),
        .clock(o_rgb0$clock)
    );
    raster_top$fragments$core$span$o_rgb1 o_rgb1(
        .d(o_rgb1$d),
        .q(o_rgb1$q),
        .clock(o_rgb1$clock)
    );
    raster_top$fragments$core$span$o_rgb2 o_rgb2(
        .d(o_rgb2$d),
        .q(o_rgb2$q),
        .clock(o_rgb2$clock)
    );
    
    // Update code
    always @(*) begin
        busy$clock = clock;
        drop$clock = clock;
        left$clock = clock;
        x$clock = clock;
        last$clock = clock;
        at_last$clock = clock;
        y$clock = clock;
        a_z$clock = clock;
        a_c0$clock = clock;
        a_c1$clock = clock;
        a_c2$clock = clock;
        d_z$clock = clock;
        d_c0$clock = clock;
        d_c1$clock = clock;
        d_c2$clock = clock;
        o_valid$clock = clock;
        o_x$clock = clock;
        o_y$clock = clock;
        o_z$clock = clock;
        o_rgb0$clock = clock;
        o_rgb1$clock = clock;
        o_rgb2$clock = clock;
        busy$d = busy$q;
        drop$d = drop$q;
        left$d = left$q;
        x$d = x$q;
        last$d = last$q;
        at_last$d = at_last$q;
        y$d = y$q;
        a_z$d = a_z$q;
        a_c0$d = a_c0$q;
        a_c1$d = a_c1$q;
        a_c2$d = a_c2$q;
        d_z$d = d_z$q;
        d_c0$d = d_c0$q;
        d_c1$d = d_c1$q;
        d_c2$d = d_c2$q;
        o_valid$d = o_valid$q;
        o_x$d = o_x$q;
        o_y$d = o_y$q;
        o_z$d = o_z$q;
        o_rgb0$d = o_rgb0$q;
        o_rgb1$d = o_rgb1$q;
        o_rgb2$d = o_rgb2$q;
        width_x = ((width) & 13'h1fff);
        zp$x = a_z$q;
        c0$x = a_c0$q;
        c1$x = a_c1$q;
        c2$x = a_c2$q;
        valid = busy$q & ~drop$q;
        if (clip_x$on & (x$q >= width_x)) begin
            valid = 1'b0;
        end
        if (clip_z$on & (zp$neg | zp$over)) begin
            valid = 1'b0;
        end
        rgb0 = c0$low;
        if (c0$over) begin
            rgb0 = 32'hff;
        end
        if (c0$neg) begin
            rgb0 = 32'h0;
        end
        rgb1 = c1$low;
        if (c1$over) begin
            rgb1 = 32'hff;
        end
        if (c1$neg) begin
            rgb1 = 32'h0;
        end
        rgb2 = c2$low;
        if (c2$over) begin
            rgb2 = 32'hff;
        end
        if (c2$neg) begin
            rgb2 = 32'h0;
        end
        out$valid = o_valid$q;
        out$x = o_x$q;
        out$y = o_y$q;
        out$z = o_z$q;
        out$rgb0 = o_rgb0$q;
        out$rgb1 = o_rgb1$q;
        out$rgb2 = o_rgb2$q;
        idle = ~busy$q & ~o_valid$q;
        x_next = x$q + 32'h1;
        if (left$q) begin
            x_next = x$q - 32'h1;
        end
        advance = busy$q & (~o_valid$q | out$ready);
        ends = drop$q | at_last$q;
        ready = ~busy$q | (ends & advance);
        inp$ready = ready;
        accept = inp$valid & ready;
        if (out$ready) begin
            o_valid$d = 1'b0;
        end
        if (advance) begin
            o_valid$d = valid;
            o_x$d = ((x$q) & 10'h3ff);
            o_y$d = y$q;
            o_z$d = zp$low;
            o_rgb0$d = rgb0;
            o_rgb1$d = rgb1;
            o_rgb2$d = rgb2;
            if (ends) begin
                busy$d = 1'b0;
            end
            else begin
                x$d = x_next;
                at_last$d = x_next == last$q;
                if (left$q) begin
                    a_z$d = a_z$q - d_z$q;
                    a_c0$d = a_c0$q - d_c0$q;
                    a_c1$d = a_c1$q - d_c1$q;
                    a_c2$d = a_c2$q - d_c2$q;
                end
                else begin
                    a_z$d = a_z$q + d_z$q;
                    a_c0$d = a_c0$q + d_c0$q;
                    a_c1$d = a_c1$q + d_c1$q;
                    a_c2$d = a_c2$q + d_c2$q;
                end
            end
        end
        zl$x = inp$left_z;
        zr$x = inp$right_z;
        xl_neg$x = inp$xl;
        xr_neg$x = inp$xr;
        xl_on$a = inp$xl;
        xl_on$b = width_x;
        dropped = 1'b0;
        if (clip_x$on & (~xl_on$lt | xr_neg$neg)) begin
            dropped = 1'b1;
        end
        if (clip_z$on & ((zl$neg & zr$neg) | (zl$over & zr$over))) begin
            dropped = 1'b1;
        end
        last_column = width_x - 32'h1;
        xr_off = clip_x$on & (inp$xr >= width_x);
        if (xl_neg$neg & clip_x$on) begin
            x_first = inp$xr;
            x_last = 32'h0;
            one_pixel = inp$xr == 32'h0;
        end
        else begin
            x_first = inp$xl;
            x_last = inp$xr;
            one_pixel = inp$xl == inp$xr;
            if (xr_off) begin
                x_last = last_column;
                one_pixel = inp$xl == last_column;
            end
        end
        if (accept) begin
            busy$d = 1'b1;
            drop$d = dropped;
            x$d = x_first;
            last$d = x_last;
            at_last$d = one_pixel;
            y$d = inp$y;
            d_z$d = ((inp$ddx_z) & 36'hfffffffff);
            d_c0$d = ((inp$ddx_c0) & 32'hffffffff);
            d_c1$d = ((inp$ddx_c1) & 32'hffffffff);
            d_c2$d = ((inp$ddx_c2) & 32'hffffffff);
            left$d = xl_neg$neg & clip_x$on;
            if (xl_neg$neg & clip_x$on) begin
                a_z$d = inp$right_z;
                a_c0$d = inp$right_c0;
                a_c1$d = inp$right_c1;
                a_c2$d = inp$right_c2;
            end
            else begin
                a_z$d = inp$left_z;
                a_c0$d = inp$left_c0;
                a_c1$d = inp$left_c1;
                a_c2$d = inp$left_c2;
            end
        end
    end
    
endmodule // raster_top$fragments$core$span


module raster_top$fragments$core$span$a_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$a_c0


module raster_top$fragments$core$span$a_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$a_c1


module raster_top$fragments$core$span$a_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$a_c2


module raster_top$fragments$core$span$a_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$a_z


module raster_top$fragments$core$span$at_last(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$at_last


module raster_top$fragments$core$span$busy(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$busy


module raster_top$fragments$core$span$c0(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    raster_top$fragments$core$span$c0$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // raster_top$fragments$core$span$c0


module raster_top$fragments$core$span$c0$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$span$c0$x_neg


module raster_top$fragments$core$span$c1(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    raster_top$fragments$core$span$c1$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // raster_top$fragments$core$span$c1


module raster_top$fragments$core$span$c1$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$span$c1$x_neg


module raster_top$fragments$core$span$c2(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    raster_top$fragments$core$span$c2$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // raster_top$fragments$core$span$c2


module raster_top$fragments$core$span$c2$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$span$c2$x_neg


module raster_top$fragments$core$span$clip_x(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // raster_top$fragments$core$span$clip_x


module raster_top$fragments$core$span$clip_z(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // raster_top$fragments$core$span$clip_z


module raster_top$fragments$core$span$d_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$d_c0


module raster_top$fragments$core$span$d_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$d_c1


module raster_top$fragments$core$span$d_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$d_c2


module raster_top$fragments$core$span$d_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$d_z


module raster_top$fragments$core$span$drop(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$drop


module raster_top$fragments$core$span$last(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$last


module raster_top$fragments$core$span$left(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$left


module raster_top$fragments$core$span$o_rgb0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$o_rgb0


module raster_top$fragments$core$span$o_rgb1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$o_rgb1


module raster_top$fragments$core$span$o_rgb2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$o_rgb2


module raster_top$fragments$core$span$o_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$o_valid


module raster_top$fragments$core$span$o_x(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$o_x


module raster_top$fragments$core$span$o_y(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$o_y


module raster_top$fragments$core$span$o_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$o_z


module raster_top$fragments$core$span$x(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$x


module raster_top$fragments$core$span$xl_neg(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$span$xl_neg


module raster_top$fragments$core$span$xl_on(a,b,lt);
    
    // Module arguments
    input wire  [12:0] a;
    input wire  [12:0] b;
    output reg  lt;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        lt = (a ^ half) < (b ^ half);
    end
    
endmodule // raster_top$fragments$core$span$xl_on


module raster_top$fragments$core$span$xr_neg(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$span$xr_neg


module raster_top$fragments$core$span$y(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$span$y


module raster_top$fragments$core$span$zl(x,neg,over);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    output reg  over;
    
    // Constant declarations
    localparam  flip = 36'h800000000;
    localparam  lo = 36'h7fffe0000;
    localparam  hi = 36'hbfffe0000;
    localparam  can_over = 1'b1;
    
    // Update code
    always @(*) begin
        neg = (x ^ flip) < lo;
        over = can_over & ((x ^ flip) >= hi);
    end
    
endmodule // raster_top$fragments$core$span$zl


module raster_top$fragments$core$span$zp(x,neg,over,low);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    output reg  over;
    output reg  [15:0] low;
    
    // Constant declarations
    localparam  top = 37'h1000000000;
    localparam  half = 37'h20000;
    localparam  shift = 8'h12;
    localparam  limit = 37'h10000;
    
    // Stub signals
    reg  [35:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [36:0] ext;
    reg  [36:0] sum;
    reg  [36:0] shifted;
    
    // Sub module instances
    raster_top$fragments$core$span$zp$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 37'h1fffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 37'h1fffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 16'hffff);
    end
    
endmodule // raster_top$fragments$core$span$zp


module raster_top$fragments$core$span$zp$x_neg(x,neg);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 36'h800000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // raster_top$fragments$core$span$zp$x_neg


module raster_top$fragments$core$span$zr(x,neg,over);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    output reg  over;
    
    // Constant declarations
    localparam  flip = 36'h800000000;
    localparam  lo = 36'h7fffe0000;
    localparam  hi = 36'hbfffe0000;
    localparam  can_over = 1'b1;
    
    // Update code
    always @(*) begin
        neg = (x ^ flip) < lo;
        over = can_over & ((x ^ flip) >= hi);
    end
    
endmodule // raster_top$fragments$core$span$zr


module raster_top$fragments$core$triangle_setup(clock,inp$valid,inp$ready,inp$v0_x,inp$v0_y,inp$v0_z,inp$v0_c0,inp$v0_c1,inp$v0_c2,inp$v0_iw,inp$v1_x,inp$v1_y,inp$v1_z,inp$v1_c0,inp$v1_c1,inp$v1_c2,inp$v1_iw,inp$v2_x,inp$v2_y,inp$v2_z,inp$v2_c0,inp$v2_c1,inp$v2_c2,inp$v2_iw,inp$crosses,out$valid,out$ready,out$walk,out$maj_left,out$maj_j,out$maj_count,out$maj_x,out$maj_r,out$maj_q,out$maj_rho,out$maj_d,out$maj_at_z,out$maj_at_c0,out$maj_at_c1,out$maj_at_c2,out$maj_inc0_z,out$maj_inc0_c0,out$maj_inc0_c1,out$maj_inc0_c2,out$maj_inc1_z,out$maj_inc1_c0,out$maj_inc1_c1,out$maj_inc1_c2,out$short0_j,out$short0_count,out$short0_x,out$short0_r,out$short0_q,out$short0_rho,out$short0_d,out$short0_at_z,out$short0_at_c0,out$short0_at_c1,out$short0_at_c2,out$short0_inc0_z,out$short0_inc0_c0,out$short0_inc0_c1,out$short0_inc0_c2,out$short0_inc1_z,out$short0_inc1_c0,out$short0_inc1_c1,out$short0_inc1_c2,out$short1_j,out$short1_count,out$short1_x,out$short1_r,out$short1_q,out$short1_rho,out$short1_d,out$short1_at_z,out$short1_at_c0,out$short1_at_c1,out$short1_at_c2,out$short1_inc0_z,out$short1_inc0_c0,out$short1_inc0_c1,out$short1_inc0_c2,out$short1_inc1_z,out$short1_inc1_c0,out$short1_inc1_c1,out$short1_inc1_c2,out$ddx_z,out$ddx_c0,out$ddx_c1,out$ddx_c2,recip_mant,recip_exp,idle,out_free_next,out_hold);
    
    // Module arguments
    input wire  clock;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [15:0] inp$v0_x;
    input wire  [15:0] inp$v0_y;
    input wire  [17:0] inp$v0_z;
    input wire  [7:0] inp$v0_c0;
    input wire  [7:0] inp$v0_c1;
    input wire  [7:0] inp$v0_c2;
    input wire  [15:0] inp$v0_iw;
    input wire  [15:0] inp$v1_x;
    input wire  [15:0] inp$v1_y;
    input wire  [17:0] inp$v1_z;
    input wire  [7:0] inp$v1_c0;
    input wire  [7:0] inp$v1_c1;
    input wire  [7:0] inp$v1_c2;
    input wire  [15:0] inp$v1_iw;
    input wire  [15:0] inp$v2_x;
    input wire  [15:0] inp$v2_y;
    input wire  [17:0] inp$v2_z;
    input wire  [7:0] inp$v2_c0;
    input wire  [7:0] inp$v2_c1;
    input wire  [7:0] inp$v2_c2;
    input wire  [15:0] inp$v2_iw;
    input wire  [5:0] inp$crosses;
    output reg  out$valid;
    input wire  out$ready;
    output reg  out$walk;
    output reg  out$maj_left;
    output reg  [12:0] out$maj_j;
    output reg  [12:0] out$maj_count;
    output reg  [12:0] out$maj_x;
    output reg  [20:0] out$maj_r;
    output reg  [16:0] out$maj_q;
    output reg  [20:0] out$maj_rho;
    output reg  [20:0] out$maj_d;
    output reg  [35:0] out$maj_at_z;
    output reg  [31:0] out$maj_at_c0;
    output reg  [31:0] out$maj_at_c1;
    output reg  [31:0] out$maj_at_c2;
    output reg  [39:0] out$maj_inc0_z;
    output reg  [35:0] out$maj_inc0_c0;
    output reg  [35:0] out$maj_inc0_c1;
    output reg  [35:0] out$maj_inc0_c2;
    output reg  [39:0] out$maj_inc1_z;
    output reg  [35:0] out$maj_inc1_c0;
    output reg  [35:0] out$maj_inc1_c1;
    output reg  [35:0] out$maj_inc1_c2;
    output reg  [12:0] out$short0_j;
    output reg  [12:0] out$short0_count;
    output reg  [12:0] out$short0_x;
    output reg  [20:0] out$short0_r;
    output reg  [16:0] out$short0_q;
    output reg  [20:0] out$short0_rho;
    output reg  [20:0] out$short0_d;
    output reg  [35:0] out$short0_at_z;
    output reg  [31:0] out$short0_at_c0;
    output reg  [31:0] out$short0_at_c1;
    output reg  [31:0] out$short0_at_c2;
    output reg  [39:0] out$short0_inc0_z;
    output reg  [35:0] out$short0_inc0_c0;
    output reg  [35:0] out$short0_inc0_c1;
    output reg  [35:0] out$short0_inc0_c2;
    output reg  [39:0] out$short0_inc1_z;
    output reg  [35:0] out$short0_inc1_c0;
    output reg  [35:0] out$short0_inc1_c1;
    output reg  [35:0] out$short0_inc1_c2;
    output reg  [12:0] out$short1_j;
    output reg  [12:0] out$short1_count;
    output reg  [12:0] out$short1_x;
    output reg  [20:0] out$short1_r;
    output reg  [16:0] out$short1_q;
    output reg  [20:0] out$short1_rho;
    output reg  [20:0] out$short1_d;
    output reg  [35:0] out$short1_at_z;
    output reg  [31:0] out$short1_at_c0;
    output reg  [31:0] out$short1_at_c1;
    output reg  [31:0] out$short1_at_c2;
    output reg  [39:0] out$short1_inc0_z;
    output reg  [35:0] out$short1_inc0_c0;
    output reg  [35:0] out$short1_inc0_c1;
    output reg  [35:0] out$short1_inc0_c2;
    output reg  [39:0] out$short1_inc1_z;
    output reg  [35:0] out$short1_inc1_c0;
    output reg  [35:0] out$short1_inc1_c1;
    output reg  [35:0] out$short1_inc1_c2;
    output reg  [39:0] out$ddx_z;
    output reg  [35:0] out$ddx_c0;
    output reg  [35:0] out$ddx_c1;
    output reg  [35:0] out$ddx_c2;
    output reg  [24:0] recip_mant;
    output reg  [5:0] recip_exp;
    output reg  idle;
    input wire  out_free_next;
    input wire  out_hold;
    
    // Constant declarations
    localparam  q_msb = 8'h12;
    localparam  q_ext = 19'b0;
    localparam  lane$0 = 8'h0;
    localparam  lane$1 = 8'h1;
    localparam  lane$2 = 8'h2;
    localparam  lane$3 = 8'h3;
    localparam  lane$4 = 8'h4;
    localparam  lane$5 = 8'h5;
    localparam  lane$6 = 8'h6;
    localparam  lane$7 = 8'h0;
    localparam  lane$8 = 8'h0;
    localparam  lane$9 = 8'h1;
    localparam  lane$10 = 8'h2;
    localparam  lane$11 = 8'h3;
    localparam  lane$12 = 8'h0;
    localparam  lane$13 = 8'h1;
    localparam  lane$14 = 8'h2;
    localparam  lane$15 = 8'h3;
    localparam  lane$16 = 8'h4;
    localparam  lane$17 = 8'h5;
    localparam  lane$18 = 8'h6;
    localparam  lane$19 = 8'h0;
    localparam  lane$20 = 8'h1;
    localparam  lane$21 = 8'h2;
    localparam  lane$22 = 8'h3;
    localparam  lane$23 = 8'h4;
    localparam  lane$24 = 8'h5;
    localparam  lane$25 = 8'h6;
    localparam  lane$26 = 8'h0;
    localparam  lane$27 = 8'h1;
    localparam  lane$28 = 8'h1;
    localparam  lane$29 = 8'h2;
    localparam  lane$30 = 8'h3;
    localparam  lane$31 = 8'h0;
    localparam  lane$32 = 8'h1;
    localparam  lane$33 = 8'h2;
    localparam  lane$34 = 8'h3;
    localparam  lane$35 = 8'h4;
    localparam  lane$36 = 8'h5;
    localparam  lane$37 = 8'h4;
    localparam  lane$38 = 8'h5;
    localparam  lane$39 = 8'h6;
    localparam  lane$40 = 8'h4;
    localparam  lane$41 = 8'h5;
    localparam  lane$42 = 8'h6;
    localparam  lane$43 = 8'h6;
    localparam  lane$44 = 8'h0;
    localparam  lane$45 = 8'h1;
    localparam  lane$46 = 8'h2;
    localparam  lane$47 = 8'h3;
    localparam  lane$48 = 8'h4;
    localparam  lane$49 = 8'h0;
    localparam  lane$50 = 8'h1;
    localparam  lane$51 = 8'h2;
    localparam  lane$52 = 8'h4;
    localparam  lane$53 = 8'h5;
    localparam  lane$54 = 8'h6;
    localparam  lane$55 = 8'h5;
    localparam  lane$56 = 8'h6;
    localparam  lane$57 = 8'h0;
    localparam  lane$58 = 8'h1;
    localparam  lane$59 = 8'h2;
    localparam  lane$60 = 8'h3;
    localparam  lane$61 = 8'h3;
    localparam  lane$62 = 8'h4;
    localparam  lane$63 = 8'h5;
    localparam  view$0 = 8'h0;
    localparam  view$1 = 8'h0;
    localparam  view$2 = 8'h0;
    localparam  view$3 = 8'h0;
    localparam  view$4 = 8'h0;
    localparam  view$5 = 8'h0;
    localparam  view$6 = 8'h0;
    localparam  view$7 = 8'h0;
    localparam  view$8 = 8'h3;
    localparam  view$9 = 8'h3;
    localparam  view$10 = 8'h3;
    localparam  view$11 = 8'h3;
    localparam  view$12 = 8'h3;
    localparam  view$13 = 8'h3;
    localparam  view$14 = 8'h3;
    localparam  view$15 = 8'h3;
    localparam  view$16 = 8'h3;
    localparam  view$17 = 8'h3;
    localparam  view$18 = 8'h3;
    localparam  view$19 = 8'h3;
    localparam  view$20 = 8'h3;
    localparam  view$21 = 8'h3;
    localparam  view$22 = 8'h3;
    localparam  view$23 = 8'h3;
    localparam  view$24 = 8'h3;
    localparam  view$25 = 8'h3;
    localparam  view$26 = 8'h3;
    localparam  view$27 = 8'h3;
    localparam  view$28 = 8'h4;
    localparam  view$29 = 8'h4;
    localparam  view$30 = 8'h4;
    localparam  view$31 = 8'h4;
    localparam  view$32 = 8'h4;
    localparam  view$33 = 8'h4;
    localparam  view$34 = 8'h4;
    localparam  view$35 = 8'h4;
    localparam  view$36 = 8'h4;
    localparam  view$37 = 8'h4;
    localparam  view$38 = 8'h4;
    localparam  view$39 = 8'h4;
    localparam  view$40 = 8'h4;
    localparam  view$41 = 8'h4;
    localparam  view$42 = 8'h4;
    localparam  view$43 = 8'h4;
    localparam  view$44 = 8'h4;
    localparam  view$45 = 8'h4;
    localparam  view$46 = 8'h4;
    localparam  view$47 = 8'h4;
    localparam  view$48 = 8'h4;
    localparam  view$49 = 8'h4;
    localparam  view$50 = 8'h4;
    localparam  view$51 = 8'h4;
    localparam  view$52 = 8'h4;
    localparam  view$53 = 8'h4;
    localparam  view$54 = 8'h4;
    localparam  view$55 = 8'h4;
    localparam  view$56 = 8'h4;
    localparam  view$57 = 8'h4;
    localparam  view$58 = 8'h4;
    localparam  view$59 = 8'h4;
    localparam  view$60 = 8'h4;
    localparam  view$61 = 8'h4;
    localparam  view$62 = 8'h4;
    localparam  view$63 = 8'h4;
    localparam  view_add$0 = 8'h0;
    localparam  view_add$1 = 8'h0;
    localparam  view_add$2 = 8'h0;
    localparam  view_add$3 = 8'h0;
    localparam  view_add$4 = 8'h0;
    localparam  view_add$5 = 8'h0;
    localparam  view_add$6 = 8'h0;
    localparam  view_add$7 = 8'h0;
    localparam  view_add$8 = 8'h3;
    localparam  view_add$9 = 8'h3;
    localparam  view_add$10 = 8'h3;
    localparam  view_add$11 = 8'h3;
    localparam  view_add$12 = 8'h4;
    localparam  view_add$13 = 8'h4;
    localparam  view_add$14 = 8'h4;
    localparam  view_add$15 = 8'h4;
    localparam  view_add$16 = 8'h4;
    localparam  view_add$17 = 8'h4;
    localparam  view_add$18 = 8'h4;
    localparam  view_add$19 = 8'h4;
    localparam  view_add$20 = 8'h4;
    localparam  view_add$21 = 8'h4;
    localparam  view_add$22 = 8'h4;
    localparam  view_add$23 = 8'h4;
    localparam  view_add$24 = 8'h4;
    localparam  view_add$25 = 8'h4;
    localparam  view_add$26 = 8'h4;
    localparam  view_add$27 = 8'h4;
    localparam  view_add$28 = 8'h4;
    localparam  view_add$29 = 8'h4;
    localparam  view_add$30 = 8'h4;
    localparam  view_add$31 = 8'h4;
    localparam  view_add$32 = 8'h4;
    localparam  view_add$33 = 8'h4;
    localparam  view_add$34 = 8'h4;
    localparam  view_add$35 = 8'h4;
    localparam  view_add$36 = 8'h4;
    localparam  view_add$37 = 8'h4;
    localparam  view_add$38 = 8'h4;
    localparam  view_add$39 = 8'h4;
    localparam  view_add$40 = 8'h4;
    localparam  view_add$41 = 8'h4;
    localparam  view_add$42 = 8'h4;
    localparam  view_add$43 = 8'h4;
    localparam  view_add$44 = 8'h4;
    localparam  view_add$45 = 8'h4;
    localparam  view_add$46 = 8'h4;
    localparam  view_add$47 = 8'h4;
    localparam  view_add$48 = 8'h4;
    localparam  view_add$49 = 8'h4;
    localparam  view_add$50 = 8'h4;
    localparam  view_add$51 = 8'h4;
    localparam  view_add$52 = 8'h4;
    localparam  view_add$53 = 8'h4;
    localparam  view_add$54 = 8'h4;
    localparam  view_add$55 = 8'h4;
    localparam  view_add$56 = 8'h4;
    localparam  view_add$57 = 8'h4;
    localparam  view_add$58 = 8'h4;
    localparam  view_add$59 = 8'h4;
    localparam  view_add$60 = 8'h4;
    localparam  view_add$61 = 8'h4;
    localparam  view_add$62 = 8'h4;
    localparam  view_add$63 = 8'h4;
    localparam  view_res$0 = 8'h3;
    localparam  view_res$1 = 8'h3;
    localparam  view_res$2 = 8'h2;
    localparam  view_res$3 = 8'h3;
    localparam  view_res$4 = 8'h2;
    localparam  view_res$5 = 8'h3;
    localparam  view_res$6 = 8'h2;
    localparam  view_res_w$0 = 8'h3;
    localparam  view_res_w$1 = 8'h3;
    localparam  view_res_w$2 = 8'h2;
    localparam  view_res_w$3 = 8'h3;
    localparam  view_res_w$4 = 8'h2;
    localparam  view_res_w$5 = 8'h3;
    localparam  view_res_w$6 = 8'h2;
    localparam  view_handover = 8'h5;
    localparam  act_bit$0 = 8'h0;
    localparam  act_bit$1 = 8'h0;
    localparam  act_bit$2 = 8'h0;
    localparam  act_bit$3 = 8'h0;
    localparam  act_bit$4 = 8'h0;
    localparam  act_bit$5 = 8'h0;
    localparam  act_bit$6 = 8'h0;
    localparam  act_bit$7 = 8'h1;
    localparam  act_bit$8 = 8'h2;
    localparam  act_bit$9 = 8'h2;
    localparam  act_bit$10 = 8'h2;
    localparam  act_bit$11 = 8'h2;
    localparam  act_bit$12 = 8'h7;
    localparam  act_bit$13 = 8'h7;
    localparam  act_bit$14 = 8'h7;
    localparam  act_bit$15 = 8'h7;
    localparam  act_bit$16 = 8'h7;
    localparam  act_bit$17 = 8'h7;
    localparam  act_bit$18 = 8'h7;
    localparam  act_bit$19 = 8'h8;
    localparam  act_bit$20 = 8'h8;
    localparam  act_bit$21 = 8'h8;
    localparam  act_bit$22 = 8'h8;
    localparam  act_bit$23 = 8'h8;
    localparam  act_bit$24 = 8'h8;
    localparam  act_bit$25 = 8'h8;
    localparam  act_bit$26 = 8'h9;
    localparam  act_bit$27 = 8'h9;
    localparam  act_bit$28 = 8'h1;
    localparam  act_bit$29 = 8'h1;
    localparam  act_bit$30 = 8'h1;
    localparam  act_bit$31 = 8'h3;
    localparam  act_bit$32 = 8'h3;
    localparam  act_bit$33 = 8'h3;
    localparam  act_bit$34 = 8'h3;
    localparam  act_bit$35 = 8'h3;
    localparam  act_bit$36 = 8'h3;
    localparam  act_bit$37 = 8'h5;
    localparam  act_bit$38 = 8'h5;
    localparam  act_bit$39 = 8'h5;
    localparam  act_bit$40 = 8'h1;
    localparam  act_bit$41 = 8'h1;
    localparam  act_bit$42 = 8'h1;
    localparam  act_bit$43 = 8'h3;
    localparam  act_bit$44 = 8'h4;
    localparam  act_bit$45 = 8'h4;
    localparam  act_bit$46 = 8'h4;
    localparam  act_bit$47 = 8'h4;
    localparam  act_bit$48 = 8'h4;
    localparam  act_bit$49 = 8'h6;
    localparam  act_bit$50 = 8'h6;
    localparam  act_bit$51 = 8'h6;
    localparam  act_bit$52 = 8'h2;
    localparam  act_bit$53 = 8'h2;
    localparam  act_bit$54 = 8'h2;
    localparam  act_bit$55 = 8'h4;
    localparam  act_bit$56 = 8'h4;
    localparam  act_bit$57 = 8'h5;
    localparam  act_bit$58 = 8'h5;
    localparam  act_bit$59 = 8'h5;
    localparam  act_bit$60 = 8'h5;
    localparam  act_bit$61 = 8'h6;
    localparam  act_bit$62 = 8'h6;
    localparam  act_bit$63 = 8'h6;
    localparam  add_bit$0 = 8'h3;
    localparam  add_bit$1 = 8'h3;
    localparam  add_bit$2 = 8'h3;
    localparam  add_bit$3 = 8'h3;
    localparam  add_bit$4 = 8'h3;
    localparam  add_bit$5 = 8'h3;
    localparam  add_bit$6 = 8'h3;
    localparam  add_bit$7 = 8'h4;
    localparam  add_bit$8 = 8'h5;
    localparam  add_bit$9 = 8'h5;
    localparam  add_bit$10 = 8'h5;
    localparam  add_bit$11 = 8'h5;
    localparam  add_bit$12 = 8'h0;
    localparam  add_bit$13 = 8'h0;
    localparam  add_bit$14 = 8'h0;
    localparam  add_bit$15 = 8'h0;
    localparam  add_bit$16 = 8'h0;
    localparam  add_bit$17 = 8'h0;
    localparam  add_bit$18 = 8'h0;
    localparam  add_bit$19 = 8'h1;
    localparam  add_bit$20 = 8'h1;
    localparam  add_bit$21 = 8'h1;
    localparam  add_bit$22 = 8'h1;
    localparam  add_bit$23 = 8'h1;
    localparam  add_bit$24 = 8'h1;
    localparam  add_bit$25 = 8'h1;
    localparam  add_bit$26 = 8'h2;
    localparam  add_bit$27 = 8'h2;
    localparam  add_bit$28 = 8'h4;
    localparam  add_bit$29 = 8'h4;
    localparam  add_bit$30 = 8'h4;
    localparam  add_bit$31 = 8'h6;
    localparam  add_bit$32 = 8'h6;
    localparam  add_bit$33 = 8'h6;
    localparam  add_bit$34 = 8'h6;
    localparam  add_bit$35 = 8'h6;
    localparam  add_bit$36 = 8'h6;
    localparam  add_bit$37 = 8'h8;
    localparam  add_bit$38 = 8'h8;
    localparam  add_bit$39 = 8'h8;
    localparam  add_bit$40 = 8'h4;
    localparam  add_bit$41 = 8'h4;
    localparam  add_bit$42 = 8'h4;
    localparam  add_bit$43 = 8'h6;
    localparam  add_bit$44 = 8'h7;
    localparam  add_bit$45 = 8'h7;
    localparam  add_bit$46 = 8'h7;
    localparam  add_bit$47 = 8'h7;
    localparam  add_bit$48 = 8'h7;
    localparam  add_bit$49 = 8'h9;
    localparam  add_bit$50 = 8'h9;
    localparam  add_bit$51 = 8'h9;
    localparam  add_bit$52 = 8'h5;
    localparam  add_bit$53 = 8'h5;
    localparam  add_bit$54 = 8'h5;
    localparam  add_bit$55 = 8'h7;
    localparam  add_bit$56 = 8'h7;
    localparam  add_bit$57 = 8'h8;
    localparam  add_bit$58 = 8'h8;
    localparam  add_bit$59 = 8'h8;
    localparam  add_bit$60 = 8'h8;
    localparam  add_bit$61 = 8'h9;
    localparam  add_bit$62 = 8'h9;
    localparam  add_bit$63 = 8'h9;
    localparam  norm_bit = 8'h4;
    localparam  iss_bit$0 = 8'h5;
    localparam  iss_bit$1 = 8'h4;
    localparam  iss_bit$2 = 8'h0;
    localparam  iss_bit$3 = 8'h6;
    localparam  iss_bit$4 = 8'h1;
    localparam  iss_bit$5 = 8'h7;
    localparam  iss_bit$6 = 8'h2;
    localparam  res_bit$0 = 8'h1;
    localparam  res_bit$1 = 8'h0;
    localparam  res_bit$2 = 8'h6;
    localparam  res_bit$3 = 8'h2;
    localparam  res_bit$4 = 8'h7;
    localparam  res_bit$5 = 8'h3;
    localparam  res_bit$6 = 8'h8;
    localparam  handover_bit = 8'h0;
    localparam  last_bit = 8'h1;
    localparam  end_bit$0 = 8'h9;
    localparam  end_bit$1 = 8'h9;
    localparam  end_bit$2 = 8'h9;
    localparam  end_bit$3 = 8'h9;
    localparam  end_bit$4 = 8'h9;
    localparam  tok_mask$0 = 64'h3ff;
    localparam  tok_mask$1 = 64'h3ff;
    localparam  tok_mask$2 = 64'h3ff;
    localparam  tok_mask$3 = 64'h3ff;
    localparam  tok_mask$4 = 64'h3ff;
    localparam  tok_mask$5 = 64'h3;
    localparam  ii_m1 = 8'h9;
    localparam  recip_n = 58'h100000000000000;
    localparam  recip_top = 6'b100000;
    localparam  bit_index$0 = 6'b0;
    localparam  bit_index$1 = 6'b1;
    localparam  bit_index$2 = 6'b10;
    localparam  bit_index$3 = 6'b11;
    localparam  bit_index$4 = 6'b100;
    localparam  bit_index$5 = 6'b101;
    localparam  bit_index$6 = 6'b110;
    localparam  bit_index$7 = 6'b111;
    localparam  bit_index$8 = 6'b1000;
    localparam  bit_index$9 = 6'b1001;
    localparam  bit_index$10 = 6'b1010;
    localparam  bit_index$11 = 6'b1011;
    localparam  bit_index$12 = 6'b1100;
    localparam  bit_index$13 = 6'b1101;
    localparam  bit_index$14 = 6'b1110;
    localparam  bit_index$15 = 6'b1111;
    localparam  bit_index$16 = 6'b10000;
    localparam  bit_index$17 = 6'b10001;
    localparam  bit_index$18 = 6'b10010;
    localparam  bit_index$19 = 6'b10011;
    localparam  bit_index$20 = 6'b10100;
    localparam  bit_index$21 = 6'b10101;
    localparam  bit_index$22 = 6'b10110;
    localparam  bit_index$23 = 6'b10111;
    localparam  bit_index$24 = 6'b11000;
    localparam  bit_index$25 = 6'b11001;
    localparam  bit_index$26 = 6'b11010;
    localparam  bit_index$27 = 6'b11011;
    localparam  bit_index$28 = 6'b11100;
    localparam  bit_index$29 = 6'b11101;
    localparam  bit_index$30 = 6'b11110;
    localparam  bit_index$31 = 6'b11111;
    localparam  bit_index$32 = 6'b100000;
    localparam  bit_index$33 = 6'b100001;
    localparam  bit_index$34 = 6'b100010;
    localparam  bit_index$35 = 6'b100011;
    localparam  eq_shift = 6'b1111;
    localparam  gsh$0 = 8'h11;
    localparam  gsh$1 = 8'hd;
    localparam  gsh$2 = 8'hd;
    localparam  gsh$3 = 8'hd;
    localparam  bsh$0 = 8'h12;
    localparam  bsh$1 = 8'h16;
    localparam  bsh$2 = 8'h16;
    localparam  bsh$3 = 8'h16;
    localparam  frac = 8'h4;
    localparam  area_msb = 8'h21;
    localparam  p_msb = 8'h38;
    localparam  ones = 57'h1ffffffffffffff;
    
    // Stub signals
    reg  mul$0$clock;
    reg  mul$0$en;
    reg  [56:0] mul$0$a;
    reg  [18:0] mul$0$b;
    wire  [57:0] mul$0$p;
    reg  mul$1$clock;
    reg  mul$1$en;
    reg  [56:0] mul$1$a;
    reg  [18:0] mul$1$b;
    wire  [57:0] mul$1$p;
    reg  mul$2$clock;
    reg  mul$2$en;
    reg  [56:0] mul$2$a;
    reg  [18:0] mul$2$b;
    wire  [57:0] mul$2$p;
    reg  mul$3$clock;
    reg  mul$3$en;
    reg  [56:0] mul$3$a;
    reg  [18:0] mul$3$b;
    wire  [57:0] mul$3$p;
    reg  mul$4$clock;
    reg  mul$4$en;
    reg  [56:0] mul$4$a;
    reg  [18:0] mul$4$b;
    wire  [57:0] mul$4$p;
    reg  mul$5$clock;
    reg  mul$5$en;
    reg  [56:0] mul$5$a;
    reg  [18:0] mul$5$b;
    wire  [57:0] mul$5$p;
    reg  mul$6$clock;
    reg  mul$6$en;
    reg  [56:0] mul$6$a;
    reg  [18:0] mul$6$b;
    wire  [57:0] mul$6$p;
    reg  div$clock;
    reg  div$inp_valid;
    wire  div$inp_ready;
    reg  div$hold;
    reg  [57:0] div$inp_n;
    reg  [33:0] div$inp_d;
    wire  div$out_valid;
    reg  div$out_ready;
    wire  [25:0] div$out_q;
    wire  [33:0] div$out_r;
    reg  stall_r$d;
    wire  stall_r$q;
    reg  stall_r$clock;
    reg  [63:0] tok$0$d;
    wire  [63:0] tok$0$q;
    reg  tok$0$clock;
    reg  [63:0] tok$1$d;
    wire  [63:0] tok$1$q;
    reg  tok$1$clock;
    reg  [63:0] tok$2$d;
    wire  [63:0] tok$2$q;
    reg  tok$2$clock;
    reg  [63:0] tok$3$d;
    wire  [63:0] tok$3$q;
    reg  tok$3$clock;
    reg  [63:0] tok$4$d;
    wire  [63:0] tok$4$q;
    reg  tok$4$clock;
    reg  [63:0] tok$5$d;
    wire  [63:0] tok$5$q;
    reg  tok$5$clock;
    reg  busy_r$d;
    wire  busy_r$q;
    reg  busy_r$clock;
    reg  gate_r$d;
    wire  gate_r$q;
    reg  gate_r$clock;
    reg  [7:0] phase$d;
    wire  [7:0] phase$q;
    reg  phase$clock;
    reg  off_grid_r$d;
    wire  off_grid_r$q;
    reg  off_grid_r$clock;
    reg  [15:0] geometry$vx$0;
    reg  [15:0] geometry$vx$1;
    reg  [15:0] geometry$vx$2;
    reg  [15:0] geometry$vy$0;
    reg  [15:0] geometry$vy$1;
    reg  [15:0] geometry$vy$2;
    reg  [17:0] geometry$vz$0;
    reg  [17:0] geometry$vz$1;
    reg  [17:0] geometry$vz$2;
    reg  [7:0] geometry$vc$0;
    reg  [7:0] geometry$vc$1;
    reg  [7:0] geometry$vc$2;
    reg  [7:0] geometry$vc$3;
    reg  [7:0] geometry$vc$4;
    reg  [7:0] geometry$vc$5;
    reg  [7:0] geometry$vc$6;
    reg  [7:0] geometry$vc$7;
    reg  [7:0] geometry$vc$8;
    reg  [5:0] geometry$crosses;
    wire  [1351:0] geometry$word;
    reg  [1351:0] geo$0$d;
    wire  [1351:0] geo$0$q;
    reg  geo$0$clock;
    reg  [1351:0] geo$1$d;
    wire  [1351:0] geo$1$q;
    reg  geo$1$clock;
    reg  [1351:0] geo$2$d;
    wire  [1351:0] geo$2$q;
    reg  geo$2$clock;
    reg  [1351:0] geo$3$d;
    wire  [1351:0] geo$3$q;
    reg  geo$3$clock;
    reg  [1351:0] geo$4$d;
    wire  [1351:0] geo$4$q;
    reg  geo$4$clock;
    reg  [1351:0] geo$5$d;
    wire  [1351:0] geo$5$q;
    reg  geo$5$clock;
    reg  sign$0$d;
    wire  sign$0$q;
    reg  sign$0$clock;
    reg  sign$1$d;
    wire  sign$1$q;
    reg  sign$1$clock;
    reg  sign$2$d;
    wire  sign$2$q;
    reg  sign$2$clock;
    reg  sign$3$d;
    wire  sign$3$q;
    reg  sign$3$clock;
    reg  sign$4$d;
    wire  sign$4$q;
    reg  sign$4$clock;
    reg  sign$5$d;
    wire  sign$5$q;
    reg  sign$5$clock;
    reg  [5:0] exp$0$d;
    wire  [5:0] exp$0$q;
    reg  exp$0$clock;
    reg  [5:0] exp$1$d;
    wire  [5:0] exp$1$q;
    reg  exp$1$clock;
    reg  [5:0] exp$2$d;
    wire  [5:0] exp$2$q;
    reg  exp$2$clock;
    reg  [5:0] exp$3$d;
    wire  [5:0] exp$3$q;
    reg  exp$3$clock;
    reg  [5:0] exp$4$d;
    wire  [5:0] exp$4$q;
    reg  exp$4$clock;
    reg  [5:0] exp$5$d;
    wire  [5:0] exp$5$q;
    reg  exp$5$clock;
    reg  [24:0] mant$0$d;
    wire  [24:0] mant$0$q;
    reg  mant$0$clock;
    reg  [24:0] mant$1$d;
    wire  [24:0] mant$1$q;
    reg  mant$1$clock;
    reg  [24:0] mant$2$d;
    wire  [24:0] mant$2$q;
    reg  mant$2$clock;
    reg  [24:0] mant$3$d;
    wire  [24:0] mant$3$q;
    reg  mant$3$clock;
    reg  [24:0] mant$4$d;
    wire  [24:0] mant$4$q;
    reg  mant$4$clock;
    reg  [24:0] mant$5$d;
    wire  [24:0] mant$5$q;
    reg  mant$5$clock;
    reg  [18:0] x$0$d;
    wire  [18:0] x$0$q;
    reg  x$0$clock;
    reg  [18:0] x$1$d;
    wire  [18:0] x$1$q;
    reg  x$1$clock;
    reg  [18:0] x$2$d;
    wire  [18:0] x$2$q;
    reg  x$2$clock;
    reg  [18:0] x$3$d;
    wire  [18:0] x$3$q;
    reg  x$3$clock;
    reg  [18:0] x$4$d;
    wire  [18:0] x$4$q;
    reg  x$4$clock;
    reg  [18:0] x$5$d;
    wire  [18:0] x$5$q;
    reg  x$5$clock;
    reg  [18:0] x$6$d;
    wire  [18:0] x$6$q;
    reg  x$6$clock;
    reg  [18:0] x$7$d;
    wire  [18:0] x$7$q;
    reg  x$7$clock;
    reg  [18:0] x$8$d;
    wire  [18:0] x$8$q;
    reg  x$8$clock;
    reg  [18:0] x$9$d;
    wire  [18:0] x$9$q;
    reg  x$9$clock;
    reg  [18:0] x$10$d;
    wire  [18:0] x$10$q;
    reg  x$10$clock;
    reg  [18:0] x$11$d;
    wire  [18:0] x$11$q;
    reg  x$11$clock;
    reg  [18:0] x$12$d;
    wire  [18:0] x$12$q;
    reg  x$12$clock;
    reg  [18:0] x$13$d;
    wire  [18:0] x$13$q;
    reg  x$13$clock;
    reg  [18:0] x$14$d;
    wire  [18:0] x$14$q;
    reg  x$14$clock;
    reg  [18:0] x$15$d;
    wire  [18:0] x$15$q;
    reg  x$15$clock;
    reg  [18:0] x$16$d;
    wire  [18:0] x$16$q;
    reg  x$16$clock;
    reg  [18:0] x$17$d;
    wire  [18:0] x$17$q;
    reg  x$17$clock;
    reg  [20:0] r$0$d;
    wire  [20:0] r$0$q;
    reg  r$0$clock;
    reg  [20:0] r$1$d;
    wire  [20:0] r$1$q;
    reg  r$1$clock;
    reg  [20:0] r$2$d;
    wire  [20:0] r$2$q;
    reg  r$2$clock;
    reg  [20:0] r$3$d;
    wire  [20:0] r$3$q;
    reg  r$3$clock;
    reg  [20:0] r$4$d;
    wire  [20:0] r$4$q;
    reg  r$4$clock;
    reg  [20:0] r$5$d;
    wire  [20:0] r$5$q;
    reg  r$5$clock;
    reg  [20:0] r$6$d;
    wire  [20:0] r$6$q;
    reg  r$6$clock;
    reg  [20:0] r$7$d;
    wire  [20:0] r$7$q;
    reg  r$7$clock;
    reg  [20:0] r$8$d;
    wire  [20:0] r$8$q;
    reg  r$8$clock;
    reg  [20:0] r$9$d;
    wire  [20:0] r$9$q;
    reg  r$9$clock;
    reg  [20:0] r$10$d;
    wire  [20:0] r$10$q;
    reg  r$10$clock;
    reg  [20:0] r$11$d;
    wire  [20:0] r$11$q;
    reg  r$11$clock;
    reg  [20:0] r$12$d;
    wire  [20:0] r$12$q;
    reg  r$12$clock;
    reg  [20:0] r$13$d;
    wire  [20:0] r$13$q;
    reg  r$13$clock;
    reg  [20:0] r$14$d;
    wire  [20:0] r$14$q;
    reg  r$14$clock;
    reg  [20:0] r$15$d;
    wire  [20:0] r$15$q;
    reg  r$15$clock;
    reg  [20:0] r$16$d;
    wire  [20:0] r$16$q;
    reg  r$16$clock;
    reg  [20:0] r$17$d;
    wire  [20:0] r$17$q;
    reg  r$17$clock;
    reg  [18:0] q$0$d;
    wire  [18:0] q$0$q;
    reg  q$0$clock;
    reg  [18:0] q$1$d;
    wire  [18:0] q$1$q;
    reg  q$1$clock;
    reg  [18:0] q$2$d;
    wire  [18:0] q$2$q;
    reg  q$2$clock;
    reg  [18:0] q$3$d;
    wire  [18:0] q$3$q;
    reg  q$3$clock;
    reg  [18:0] q$4$d;
    wire  [18:0] q$4$q;
    reg  q$4$clock;
    reg  [18:0] q$5$d;
    wire  [18:0] q$5$q;
    reg  q$5$clock;
    reg  [18:0] q$6$d;
    wire  [18:0] q$6$q;
    reg  q$6$clock;
    reg  [18:0] q$7$d;
    wire  [18:0] q$7$q;
    reg  q$7$clock;
    reg  [18:0] q$8$d;
    wire  [18:0] q$8$q;
    reg  q$8$clock;
    reg  [18:0] q$9$d;
    wire  [18:0] q$9$q;
    reg  q$9$clock;
    reg  [18:0] q$10$d;
    wire  [18:0] q$10$q;
    reg  q$10$clock;
    reg  [18:0] q$11$d;
    wire  [18:0] q$11$q;
    reg  q$11$clock;
    reg  [18:0] q$12$d;
    wire  [18:0] q$12$q;
    reg  q$12$clock;
    reg  [18:0] q$13$d;
    wire  [18:0] q$13$q;
    reg  q$13$clock;
    reg  [18:0] q$14$d;
    wire  [18:0] q$14$q;
    reg  q$14$clock;
    reg  [18:0] q$15$d;
    wire  [18:0] q$15$q;
    reg  q$15$clock;
    reg  [18:0] q$16$d;
    wire  [18:0] q$16$q;
    reg  q$16$clock;
    reg  [18:0] q$17$d;
    wire  [18:0] q$17$q;
    reg  q$17$clock;
    reg  [20:0] rho$0$d;
    wire  [20:0] rho$0$q;
    reg  rho$0$clock;
    reg  [20:0] rho$1$d;
    wire  [20:0] rho$1$q;
    reg  rho$1$clock;
    reg  [20:0] rho$2$d;
    wire  [20:0] rho$2$q;
    reg  rho$2$clock;
    reg  [20:0] rho$3$d;
    wire  [20:0] rho$3$q;
    reg  rho$3$clock;
    reg  [20:0] rho$4$d;
    wire  [20:0] rho$4$q;
    reg  rho$4$clock;
    reg  [20:0] rho$5$d;
    wire  [20:0] rho$5$q;
    reg  rho$5$clock;
    reg  [20:0] rho$6$d;
    wire  [20:0] rho$6$q;
    reg  rho$6$clock;
    reg  [20:0] rho$7$d;
    wire  [20:0] rho$7$q;
    reg  rho$7$clock;
    reg  [20:0] rho$8$d;
    wire  [20:0] rho$8$q;
    reg  rho$8$clock;
    reg  [20:0] rho$9$d;
    wire  [20:0] rho$9$q;
    reg  rho$9$clock;
    reg  [20:0] rho$10$d;
    wire  [20:0] rho$10$q;
    reg  rho$10$clock;
    reg  [20:0] rho$11$d;
    wire  [20:0] rho$11$q;
    reg  rho$11$clock;
    reg  [20:0] rho$12$d;
    wire  [20:0] rho$12$q;
    reg  rho$12$clock;
    reg  [20:0] rho$13$d;
    wire  [20:0] rho$13$q;
    reg  rho$13$clock;
    reg  [20:0] rho$14$d;
    wire  [20:0] rho$14$q;
    reg  rho$14$clock;
    reg  [20:0] rho$15$d;
    wire  [20:0] rho$15$q;
    reg  rho$15$clock;
    reg  [20:0] rho$16$d;
    wire  [20:0] rho$16$q;
    reg  rho$16$clock;
    reg  [20:0] rho$17$d;
    wire  [20:0] rho$17$q;
    reg  rho$17$clock;
    reg  [1351:0] g0$word;
    reg  g0$maj_left;
    reg  [18:0] g0$start_x$0;
    reg  [18:0] g0$start_x$1;
    reg  [18:0] g0$start_x$2;
    wire  [57:0] g0$kdx$0;
    wire  [57:0] g0$kdx$1;
    wire  [57:0] g0$kdx$2;
    wire  [56:0] g0$kdy$0;
    wire  [56:0] g0$kdy$1;
    wire  [56:0] g0$kdy$2;
    wire  g0$up;
    wire  [57:0] g0$edx$0;
    wire  [57:0] g0$edx$1;
    wire  [57:0] g0$edx$2;
    wire  [56:0] g0$edy$0;
    wire  [56:0] g0$edy$1;
    wire  [56:0] g0$edy$2;
    wire  [33:0] g0$edy_d$0;
    wire  [33:0] g0$edy_d$1;
    wire  [33:0] g0$edy_d$2;
    wire  [33:0] g0$ed16$0;
    wire  [33:0] g0$ed16$1;
    wire  [33:0] g0$ed16$2;
    wire  [18:0] g0$cy$0;
    wire  [18:0] g0$cy$1;
    wire  [18:0] g0$cy$2;
    wire  [12:0] g0$count$0;
    wire  [12:0] g0$count$1;
    wire  [12:0] g0$count$2;
    wire  g0$used$0;
    wire  g0$used$1;
    wire  g0$used$2;
    wire  g0$step$0;
    wire  g0$step$1;
    wire  g0$step$2;
    wire  [18:0] g0$toff$0;
    wire  [18:0] g0$toff$1;
    wire  [18:0] g0$toff$2;
    wire  [18:0] g0$xf$0;
    wire  [18:0] g0$xf$1;
    wire  [18:0] g0$xf$2;
    wire  [18:0] g0$xi$0;
    wire  [18:0] g0$xi$1;
    wire  [18:0] g0$xi$2;
    wire  [18:0] g0$off_x$0;
    wire  [18:0] g0$off_x$1;
    wire  [18:0] g0$off_x$2;
    wire  [18:0] g0$off_y$0;
    wire  [18:0] g0$off_y$1;
    wire  [18:0] g0$off_y$2;
    wire  [18:0] g0$dmaj$0;
    wire  [18:0] g0$dmaj$1;
    wire  [18:0] g0$dmaj$2;
    wire  [18:0] g0$dmaj$3;
    wire  [18:0] g0$dbot$0;
    wire  [18:0] g0$dbot$1;
    wire  [18:0] g0$dbot$2;
    wire  [18:0] g0$dbot$3;
    wire  [39:0] g0$attr0$0;
    wire  [39:0] g0$attr0$1;
    wire  [39:0] g0$attr0$2;
    wire  [39:0] g0$attr0$3;
    reg  [1351:0] g1$word;
    reg  g1$maj_left;
    reg  [18:0] g1$start_x$0;
    reg  [18:0] g1$start_x$1;
    reg  [18:0] g1$start_x$2;
    wire  [57:0] g1$kdx$0;
    wire  [57:0] g1$kdx$1;
    wire  [57:0] g1$kdx$2;
    wire  [56:0] g1$kdy$0;
    wire  [56:0] g1$kdy$1;
    wire  [56:0] g1$kdy$2;
    wire  g1$up;
    wire  [57:0] g1$edx$0;
    wire  [57:0] g1$edx$1;
    wire  [57:0] g1$edx$2;
    wire  [56:0] g1$edy$0;
    wire  [56:0] g1$edy$1;
    wire  [56:0] g1$edy$2;
    wire  [33:0] g1$edy_d$0;
    wire  [33:0] g1$edy_d$1;
    wire  [33:0] g1$edy_d$2;
    wire  [33:0] g1$ed16$0;
    wire  [33:0] g1$ed16$1;
    wire  [33:0] g1$ed16$2;
    wire  [18:0] g1$cy$0;
    wire  [18:0] g1$cy$1;
    wire  [18:0] g1$cy$2;
    wire  [12:0] g1$count$0;
    wire  [12:0] g1$count$1;
    wire  [12:0] g1$count$2;
    wire  g1$used$0;
    wire  g1$used$1;
    wire  g1$used$2;
    wire  g1$step$0;
    wire  g1$step$1;
    wire  g1$step$2;
    wire  [18:0] g1$toff$0;
    wire  [18:0] g1$toff$1;
    wire  [18:0] g1$toff$2;
    wire  [18:0] g1$xf$0;
    wire  [18:0] g1$xf$1;
    wire  [18:0] g1$xf$2;
    wire  [18:0] g1$xi$0;
    wire  [18:0] g1$xi$1;
    wire  [18:0] g1$xi$2;
    wire  [18:0] g1$off_x$0;
    wire  [18:0] g1$off_x$1;
    wire  [18:0] g1$off_x$2;
    wire  [18:0] g1$off_y$0;
    wire  [18:0] g1$off_y$1;
    wire  [18:0] g1$off_y$2;
    wire  [18:0] g1$dmaj$0;
    wire  [18:0] g1$dmaj$1;
    wire  [18:0] g1$dmaj$2;
    wire  [18:0] g1$dmaj$3;
    wire  [18:0] g1$dbot$0;
    wire  [18:0] g1$dbot$1;
    wire  [18:0] g1$dbot$2;
    wire  [18:0] g1$dbot$3;
    wire  [39:0] g1$attr0$0;
    wire  [39:0] g1$attr0$1;
    wire  [39:0] g1$attr0$2;
    wire  [39:0] g1$attr0$3;
    reg  [1351:0] g2$word;
    reg  g2$maj_left;
    reg  [18:0] g2$start_x$0;
    reg  [18:0] g2$start_x$1;
    reg  [18:0] g2$start_x$2;
    wire  [57:0] g2$kdx$0;
    wire  [57:0] g2$kdx$1;
    wire  [57:0] g2$kdx$2;
    wire  [56:0] g2$kdy$0;
    wire  [56:0] g2$kdy$1;
    wire  [56:0] g2$kdy$2;
    wire  g2$up;
    wire  [57:0] g2$edx$0;
    wire  [57:0] g2$edx$1;
    wire  [57:0] g2$edx$2;
    wire  [56:0] g2$edy$0;
    wire  [56:0] g2$edy$1;
    wire  [56:0] g2$edy$2;
    wire  [33:0] g2$edy_d$0;
    wire  [33:0] g2$edy_d$1;
    wire  [33:0] g2$edy_d$2;
    wire  [33:0] g2$ed16$0;
    wire  [33:0] g2$ed16$1;
    wire  [33:0] g2$ed16$2;
    wire  [18:0] g2$cy$0;
    wire  [18:0] g2$cy$1;
    wire  [18:0] g2$cy$2;
    wire  [12:0] g2$count$0;
    wire  [12:0] g2$count$1;
    wire  [12:0] g2$count$2;
    wire  g2$used$0;
    wire  g2$used$1;
    wire  g2$used$2;
    wire  g2$step$0;
    wire  g2$step$1;
    wire  g2$step$2;
    wire  [18:0] g2$toff$0;
    wire  [18:0] g2$toff$1;
    wire  [18:0] g2$toff$2;
    wire  [18:0] g2$xf$0;
    wire  [18:0] g2$xf$1;
    wire  [18:0] g2$xf$2;
    wire  [18:0] g2$xi$0;
    wire  [18:0] g2$xi$1;
    wire  [18:0] g2$xi$2;
    wire  [18:0] g2$off_x$0;
    wire  [18:0] g2$off_x$1;
    wire  [18:0] g2$off_x$2;
    wire  [18:0] g2$off_y$0;
    wire  [18:0] g2$off_y$1;
    wire  [18:0] g2$off_y$2;
    wire  [18:0] g2$dmaj$0;
    wire  [18:0] g2$dmaj$1;
    wire  [18:0] g2$dmaj$2;
    wire  [18:0] g2$dmaj$3;
    wire  [18:0] g2$dbot$0;
    wire  [18:0] g2$dbot$1;
    wire  [18:0] g2$dbot$2;
    wire  [18:0] g2$dbot$3;
    wire  [39:0] g2$attr0$0;
    wire  [39:0] g2$attr0$1;
    wire  [39:0] g2$attr0$2;
    wire  [39:0] g2$attr0$3;
    reg  [1351:0] g3$word;
    reg  g3$maj_left;
    reg  [18:0] g3$start_x$0;
    reg  [18:0] g3$start_x$1;
    reg  [18:0] g3$start_x$2;
    wire  [57:0] g3$kdx$0;
    wire  [57:0] g3$kdx$1;
    wire  [57:0] g3$kdx$2;
    wire  [56:0] g3$kdy$0;
    wire  [56:0] g3$kdy$1;
    wire  [56:0] g3$kdy$2;
    wire  g3$up;
    wire  [57:0] g3$edx$0;
    wire  [57:0] g3$edx$1;
    wire  [57:0] g3$edx$2;
    wire  [56:0] g3$edy$0;
    wire  [56:0] g3$edy$1;
    wire  [56:0] g3$edy$2;
    wire  [33:0] g3$edy_d$0;
    wire  [33:0] g3$edy_d$1;
    wire  [33:0] g3$edy_d$2;
    wire  [33:0] g3$ed16$0;
    wire  [33:0] g3$ed16$1;
    wire  [33:0] g3$ed16$2;
    wire  [18:0] g3$cy$0;
    wire  [18:0] g3$cy$1;
    wire  [18:0] g3$cy$2;
    wire  [12:0] g3$count$0;
    wire  [12:0] g3$count$1;
    wire  [12:0] g3$count$2;
    wire  g3$used$0;
    wire  g3$used$1;
    wire  g3$used$2;
    wire  g3$step$0;
    wire  g3$step$1;
    wire  g3$step$2;
    wire  [18:0] g3$toff$0;
    wire  [18:0] g3$toff$1;
    wire  [18:0] g3$toff$2;
    wire  [18:0] g3$xf$0;
    wire  [18:0] g3$xf$1;
    wire  [18:0] g3$xf$2;
    wire  [18:0] g3$xi$0;
    wire  [18:0] g3$xi$1;
    wire  [18:0] g3$xi$2;
    wire  [18:0] g3$off_x$0;
    wire  [18:0] g3$off_x$1;
    wire  [18:0] g3$off_x$2;
    wire  [18:0] g3$off_y$0;
    wire  [18:0] g3$off_y$1;
    wire  [18:0] g3$off_y$2;
    wire  [18:0] g3$dmaj$0;
    wire  [18:0] g3$dmaj$1;
    wire  [18:0] g3$dmaj$2;
    wire  [18:0] g3$dmaj$3;
    wire  [18:0] g3$dbot$0;
    wire  [18:0] g3$dbot$1;
    wire  [18:0] g3$dbot$2;
    wire  [18:0] g3$dbot$3;
    wire  [39:0] g3$attr0$0;
    wire  [39:0] g3$attr0$1;
    wire  [39:0] g3$attr0$2;
    wire  [39:0] g3$attr0$3;
    reg  [1351:0] g4$word;
    reg  g4$maj_left;
    reg  [18:0] g4$start_x$0;
    reg  [18:0] g4$start_x$1;
    reg  [18:0] g4$start_x$2;
    wire  [57:0] g4$kdx$0;
    wire  [57:0] g4$kdx$1;
    wire  [57:0] g4$kdx$2;
    wire  [56:0] g4$kdy$0;
    wire  [56:0] g4$kdy$1;
    wire  [56:0] g4$kdy$2;
    wire  g4$up;
    wire  [57:0] g4$edx$0;
    wire  [57:0] g4$edx$1;
    wire  [57:0] g4$edx$2;
    wire  [56:0] g4$edy$0;
    wire  [56:0] g4$edy$1;
    wire  [56:0] g4$edy$2;
    wire  [33:0] g4$edy_d$0;
    wire  [33:0] g4$edy_d$1;
    wire  [33:0] g4$edy_d$2;
    wire  [33:0] g4$ed16$0;
    wire  [33:0] g4$ed16$1;
    wire  [33:0] g4$ed16$2;
    wire  [18:0] g4$cy$0;
    wire  [18:0] g4$cy$1;
    wire  [18:0] g4$cy$2;
    wire  [12:0] g4$count$0;
    wire  [12:0] g4$count$1;
    wire  [12:0] g4$count$2;
    wire  g4$used$0;
    wire  g4$used$1;
    wire  g4$used$2;
    wire  g4$step$0;
    wire  g4$step$1;
    wire  g4$step$2;
    wire  [18:0] g4$toff$0;
    wire  [18:0] g4$toff$1;
    wire  [18:0] g4$toff$2;
    wire  [18:0] g4$xf$0;
    wire  [18:0] g4$xf$1;
    wire  [18:0] g4$xf$2;
    wire  [18:0] g4$xi$0;
    wire  [18:0] g4$xi$1;
    wire  [18:0] g4$xi$2;
    wire  [18:0] g4$off_x$0;
    wire  [18:0] g4$off_x$1;
    wire  [18:0] g4$off_x$2;
    wire  [18:0] g4$off_y$0;
    wire  [18:0] g4$off_y$1;
    wire  [18:0] g4$off_y$2;
    wire  [18:0] g4$dmaj$0;
    wire  [18:0] g4$dmaj$1;
    wire  [18:0] g4$dmaj$2;
    wire  [18:0] g4$dmaj$3;
    wire  [18:0] g4$dbot$0;
    wire  [18:0] g4$dbot$1;
    wire  [18:0] g4$dbot$2;
    wire  [18:0] g4$dbot$3;
    wire  [39:0] g4$attr0$0;
    wire  [39:0] g4$attr0$1;
    wire  [39:0] g4$attr0$2;
    wire  [39:0] g4$attr0$3;
    reg  [1351:0] g5$word;
    reg  g5$maj_left;
    reg  [18:0] g5$start_x$0;
    reg  [18:0] g5$start_x$1;
    reg  [18:0] g5$start_x$2;
    wire  [57:0] g5$kdx$0;
    wire  [57:0] g5$kdx$1;
    wire  [57:0] g5$kdx$2;
    wire  [56:0] g5$kdy$0;
    wire  [56:0] g5$kdy$1;
    wire  [56:0] g5$kdy$2;
    wire  g5$up;
    wire  [57:0] g5$edx$0;
    wire  [57:0] g5$edx$1;
    wire  [57:0] g5$edx$2;
    wire  [56:0] g5$edy$0;
    wire  [56:0] g5$edy$1;
    wire  [56:0] g5$edy$2;
    wire  [33:0] g5$edy_d$0;
    wire  [33:0] g5$edy_d$1;
    wire  [33:0] g5$edy_d$2;
    wire  [33:0] g5$ed16$0;
    wire  [33:0] g5$ed16$1;
    wire  [33:0] g5$ed16$2;
    wire  [18:0] g5$cy$0;
    wire  [18:0] g5$cy$1;
    wire  [18:0] g5$cy$2;
    wire  [12:0] g5$count$0;
    wire  [12:0] g5$count$1;
    wire  [12:0] g5$count$2;
    wire  g5$used$0;
    wire  g5$used$1;
    wire  g5$used$2;
    wire  g5$step$0;
    wire  g5$step$1;
    wire  g5$step$2;
    wire  [18:0] g5$toff$0;
    wire  [18:0] g5$toff$1;
    wire  [18:0] g5$toff$2;
    wire  [18:0] g5$xf$0;
    wire  [18:0] g5$xf$1;
    wire  [18:0] g5$xf$2;
    wire  [18:0] g5$xi$0;
    wire  [18:0] g5$xi$1;
    wire  [18:0] g5$xi$2;
    wire  [18:0] g5$off_x$0;
    wire  [18:0] g5$off_x$1;
    wire  [18:0] g5$off_x$2;
    wire  [18:0] g5$off_y$0;
    wire  [18:0] g5$off_y$1;
    wire  [18:0] g5$off_y$2;
    wire  [18:0] g5$dmaj$0;
    wire  [18:0] g5$dmaj$1;
    wire  [18:0] g5$dmaj$2;
    wire  [18:0] g5$dmaj$3;
    wire  [18:0] g5$dbot$0;
    wire  [18:0] g5$dbot$1;
    wire  [18:0] g5$dbot$2;
    wire  [18:0] g5$dbot$3;
    wire  [39:0] g5$attr0$0;
    wire  [39:0] g5$attr0$1;
    wire  [39:0] g5$attr0$2;
    wire  [39:0] g5$attr0$3;
    reg  [33:0] area$d;
    wire  [33:0] area$q;
    reg  area$clock;
    reg  [33:0] norm$d;
    wire  [33:0] norm$q;
    reg  norm$clock;
    reg  [5:0] nsh$d;
    wire  [5:0] nsh$q;
    reg  nsh$clock;
    reg  div_v$d;
    wire  div_v$q;
    reg  div_v$clock;
    reg  [57:0] div_n$d;
    wire  [57:0] div_n$q;
    reg  div_n$clock;
    reg  [33:0] div_d$d;
    wire  [33:0] div_d$q;
    reg  div_d$clock;
    reg  [56:0] mant_s$d;
    wire  [56:0] mant_s$q;
    reg  mant_s$clock;
    reg  [5:0] rsh$d;
    wire  [5:0] rsh$q;
    reg  rsh$clock;
    reg  left$d;
    wire  left$q;
    reg  left$clock;
    reg  [57:0] num$0$d;
    wire  [57:0] num$0$q;
    reg  num$0$clock;
    reg  [57:0] num$1$d;
    wire  [57:0] num$1$q;
    reg  num$1$clock;
    reg  [57:0] num$2$d;
    wire  [57:0] num$2$q;
    reg  num$2$clock;
    reg  [56:0] p$0$d;
    wire  [56:0] p$0$q;
    reg  p$0$clock;
    reg  [56:0] p$1$d;
    wire  [56:0] p$1$q;
    reg  p$1$clock;
    reg  [56:0] p$2$d;
    wire  [56:0] p$2$q;
    reg  p$2$clock;
    reg  [56:0] p$3$d;
    wire  [56:0] p$3$q;
    reg  p$3$clock;
    reg  [56:0] gx$0$d;
    wire  [56:0] gx$0$q;
    reg  gx$0$clock;
    reg  [56:0] gx$1$d;
    wire  [56:0] gx$1$q;
    reg  gx$1$clock;
    reg  [56:0] gx$2$d;
    wire  [56:0] gx$2$q;
    reg  gx$2$clock;
    reg  [56:0] gx$3$d;
    wire  [56:0] gx$3$q;
    reg  gx$3$clock;
    reg  [56:0] gy$0$d;
    wire  [56:0] gy$0$q;
    reg  gy$0$clock;
    reg  [56:0] gy$1$d;
    wire  [56:0] gy$1$q;
    reg  gy$1$clock;
    reg  [56:0] gy$2$d;
    wire  [56:0] gy$2$q;
    reg  gy$2$clock;
    reg  [56:0] gy$3$d;
    wire  [56:0] gy$3$q;
    reg  gy$3$clock;
    reg  [39:0] plane$0$d;
    wire  [39:0] plane$0$q;
    reg  plane$0$clock;
    reg  [39:0] plane$1$d;
    wire  [39:0] plane$1$q;
    reg  plane$1$clock;
    reg  [39:0] plane$2$d;
    wire  [39:0] plane$2$q;
    reg  plane$2$clock;
    reg  [39:0] plane$3$d;
    wire  [39:0] plane$3$q;
    reg  plane$3$clock;
    reg  [39:0] plane$4$d;
    wire  [39:0] plane$4$q;
    reg  plane$4$clock;
    reg  [39:0] plane$5$d;
    wire  [39:0] plane$5$q;
    reg  plane$5$clock;
    reg  [39:0] plane$6$d;
    wire  [39:0] plane$6$q;
    reg  plane$6$clock;
    reg  [39:0] plane$7$d;
    wire  [39:0] plane$7$q;
    reg  plane$7$clock;
    reg  [39:0] plane$8$d;
    wire  [39:0] plane$8$q;
    reg  plane$8$clock;
    reg  [39:0] plane$9$d;
    wire  [39:0] plane$9$q;
    reg  plane$9$clock;
    reg  [39:0] plane$10$d;
    wire  [39:0] plane$10$q;
    reg  plane$10$clock;
    reg  [39:0] plane$11$d;
    wire  [39:0] plane$11$q;
    reg  plane$11$clock;
    reg  [39:0] inc0$0$d;
    wire  [39:0] inc0$0$q;
    reg  inc0$0$clock;
    reg  [39:0] inc0$1$d;
    wire  [39:0] inc0$1$q;
    reg  inc0$1$clock;
    reg  [39:0] inc0$2$d;
    wire  [39:0] inc0$2$q;
    reg  inc0$2$clock;
    reg  [39:0] inc0$3$d;
    wire  [39:0] inc0$3$q;
    reg  inc0$3$clock;
    reg  [39:0] inc0$4$d;
    wire  [39:0] inc0$4$q;
    reg  inc0$4$clock;
    reg  [39:0] inc0$5$d;
    wire  [39:0] inc0$5$q;
    reg  inc0$5$clock;
    reg  [39:0] inc0$6$d;
    wire  [39:0] inc0$6$q;
    reg  inc0$6$clock;
    reg  [39:0] inc0$7$d;
    wire  [39:0] inc0$7$q;
    reg  inc0$7$clock;
    reg  [39:0] inc0$8$d;
    wire  [39:0] inc0$8$q;
    reg  inc0$8$clock;
    reg  [39:0] inc0$9$d;
    wire  [39:0] inc0$9$q;
    reg  inc0$9$clock;
    reg  [39:0] inc0$10$d;
    wire  [39:0] inc0$10$q;
    reg  inc0$10$clock;
    reg  [39:0] inc0$11$d;
    wire  [39:0] inc0$11$q;
    reg  inc0$11$clock;
    reg  [39:0] inc1$0$d;
    wire  [39:0] inc1$0$q;
    reg  inc1$0$clock;
    reg  [39:0] inc1$1$d;
    wire  [39:0] inc1$1$q;
    reg  inc1$1$clock;
    reg  [39:0] inc1$2$d;
    wire  [39:0] inc1$2$q;
    reg  inc1$2$clock;
    reg  [39:0] inc1$3$d;
    wire  [39:0] inc1$3$q;
    reg  inc1$3$clock;
    reg  [39:0] inc1$4$d;
    wire  [39:0] inc1$4$q;
    reg  inc1$4$clock;
    reg  [39:0] inc1$5$d;
    wire  [39:0] inc1$5$q;
    reg  inc1$5$clock;
    reg  [39:0] inc1$6$d;
    wire  [39:0] inc1$6$q;
    reg  inc1$6$clock;
    reg  [39:0] inc1$7$d;
    wire  [39:0] inc1$7$q;
    reg  inc1$7$clock;
    reg  [39:0] inc1$8$d;
    wire  [39:0] inc1$8$q;
    reg  inc1$8$clock;
    reg  [39:0] inc1$9$d;
    wire  [39:0] inc1$9$q;
    reg  inc1$9$clock;
    reg  [39:0] inc1$10$d;
    wire  [39:0] inc1$10$q;
    reg  inc1$10$clock;
    reg  [39:0] inc1$11$d;
    wire  [39:0] inc1$11$q;
    reg  inc1$11$clock;
    reg  [39:0] ddx_o$0$d;
    wire  [39:0] ddx_o$0$q;
    reg  ddx_o$0$clock;
    reg  [39:0] ddx_o$1$d;
    wire  [39:0] ddx_o$1$q;
    reg  ddx_o$1$clock;
    reg  [39:0] ddx_o$2$d;
    wire  [39:0] ddx_o$2$q;
    reg  ddx_o$2$clock;
    reg  [39:0] ddx_o$3$d;
    wire  [39:0] ddx_o$3$q;
    reg  ddx_o$3$clock;
    reg  o_walk$d;
    wire  o_walk$q;
    reg  o_walk$clock;
    reg  o_maj_left$d;
    wire  o_maj_left$q;
    reg  o_maj_left$clock;
    reg  [12:0] o_j$0$d;
    wire  [12:0] o_j$0$q;
    reg  o_j$0$clock;
    reg  [12:0] o_j$1$d;
    wire  [12:0] o_j$1$q;
    reg  o_j$1$clock;
    reg  [12:0] o_j$2$d;
    wire  [12:0] o_j$2$q;
    reg  o_j$2$clock;
    reg  [12:0] o_count$0$d;
    wire  [12:0] o_count$0$q;
    reg  o_count$0$clock;
    reg  [12:0] o_count$1$d;
    wire  [12:0] o_count$1$q;
    reg  o_count$1$clock;
    reg  [12:0] o_count$2$d;
    wire  [12:0] o_count$2$q;
    reg  o_count$2$clock;
    reg  [20:0] o_d$0$d;
    wire  [20:0] o_d$0$q;
    reg  o_d$0$clock;
    reg  [20:0] o_d$1$d;
    wire  [20:0] o_d$1$q;
    reg  o_d$1$clock;
    reg  [20:0] o_d$2$d;
    wire  [20:0] o_d$2$q;
    reg  o_d$2$clock;
    
    // Local signals
    reg  take;
    reg  run;
    reg  valid_n;
    reg  at_norm;
    reg  at_iss$0;
    reg  at_iss$1;
    reg  at_iss$2;
    reg  at_iss$3;
    reg  at_iss$4;
    reg  at_iss$5;
    reg  at_iss$6;
    reg  at_res$0;
    reg  at_res$1;
    reg  at_res$2;
    reg  at_res$3;
    reg  at_res$4;
    reg  at_res$5;
    reg  at_res$6;
    reg  at_handover;
    reg  enter$0;
    reg  enter$1;
    reg  enter$2;
    reg  enter$3;
    reg  enter$4;
    reg  enter$5;
    reg  [63:0] tok_n$0;
    reg  [63:0] tok_n$1;
    reg  [63:0] tok_n$2;
    reg  [63:0] tok_n$3;
    reg  [63:0] tok_n$4;
    reg  [63:0] tok_n$5;
    reg  act$0;
    reg  act$1;
    reg  act$2;
    reg  act$3;
    reg  act$4;
    reg  act$5;
    reg  act$6;
    reg  act$7;
    reg  act$8;
    reg  act$9;
    reg  act$10;
    reg  act$11;
    reg  act$12;
    reg  act$13;
    reg  act$14;
    reg  act$15;
    reg  act$16;
    reg  act$17;
    reg  act$18;
    reg  act$19;
    reg  act$20;
    reg  act$21;
    reg  act$22;
    reg  act$23;
    reg  act$24;
    reg  act$25;
    reg  act$26;
    reg  act$27;
    reg  act$28;
    reg  act$29;
    reg  act$30;
    reg  act$31;
    reg  act$32;
    reg  act$33;
    reg  act$34;
    reg  act$35;
    reg  act$36;
    reg  act$37;
    reg  act$38;
    reg  act$39;
    reg  act$40;
    reg  act$41;
    reg  act$42;
    reg  act$43;
    reg  act$44;
    reg  act$45;
    reg  act$46;
    reg  act$47;
    reg  act$48;
    reg  act$49;
    reg  act$50;
    reg  act$51;
    reg  act$52;
    reg  act$53;
    reg  act$54;
    reg  act$55;
    reg  act$56;
    reg  act$57;
    reg  act$58;
    reg  act$59;
    reg  act$60;
    reg  act$61;
    reg  act$62;
    reg  act$63;
    reg  add$0;
    reg  add$1;
    reg  add$2;
    reg  add$3;
    reg  add$4;
    reg  add$5;
    reg  add$6;
    reg  add$7;
    reg  add$8;
    reg  add$9;
    reg  add$10;
    reg  add$11;
    reg  add$12;
    reg  add$13;
    reg  add$14;
    reg  add$15;
    reg  add$16;
    reg  add$17;
    reg  add$18;
    reg  add$19;
    reg  add$20;
    reg  add$21;
    reg  add$22;
    reg  add$23;
    reg  add$24;
    reg  add$25;
    reg  add$26;
    reg  add$27;
    reg  add$28;
    reg  add$29;
    reg  add$30;
    reg  add$31;
    reg  add$32;
    reg  add$33;
    reg  add$34;
    reg  add$35;
    reg  add$36;
    reg  add$37;
    reg  add$38;
    reg  add$39;
    reg  add$40;
    reg  add$41;
    reg  add$42;
    reg  add$43;
    reg  add$44;
    reg  add$45;
    reg  add$46;
    reg  add$47;
    reg  add$48;
    reg  add$49;
    reg  add$50;
    reg  add$51;
    reg  add$52;
    reg  add$53;
    reg  add$54;
    reg  add$55;
    reg  add$56;
    reg  add$57;
    reg  add$58;
    reg  add$59;
    reg  add$60;
    reg  add$61;
    reg  add$62;
    reg  add$63;
    reg  valid;
    reg  busy_n;
    reg  off_grid_n;
    reg  maj_left$0;
    reg  maj_left$1;
    reg  maj_left$2;
    reg  maj_left$3;
    reg  maj_left$4;
    reg  maj_left$5;
    reg  [33:0] area_abs;
    reg  [35:0] abs_p;
    reg  nib_any$0;
    reg  nib_any$1;
    reg  nib_any$2;
    reg  nib_any$3;
    reg  nib_any$4;
    reg  nib_any$5;
    reg  nib_any$6;
    reg  nib_any$7;
    reg  nib_any$8;
    reg  [5:0] nib_pos$0;
    reg  [5:0] nib_pos$1;
    reg  [5:0] nib_pos$2;
    reg  [5:0] nib_pos$3;
    reg  [5:0] nib_pos$4;
    reg  [5:0] nib_pos$5;
    reg  [5:0] nib_pos$6;
    reg  [5:0] nib_pos$7;
    reg  [5:0] nib_pos$8;
    reg  [5:0] nib_sh$0;
    reg  [5:0] nib_sh$1;
    reg  [5:0] nib_sh$2;
    reg  [5:0] nib_sh$3;
    reg  [5:0] nib_sh$4;
    reg  [5:0] nib_sh$5;
    reg  [5:0] nib_sh$6;
    reg  [5:0] nib_sh$7;
    reg  [5:0] nib_sh$8;
    reg  [5:0] exp_c;
    reg  [5:0] nsh_c;
    reg  [33:0] norm_d;
    reg  [5:0] exp_r;
    reg  [18:0] q_n;
    reg  r_pos;
    reg  [18:0] xi$0;
    reg  [18:0] xi$1;
    reg  [18:0] xi$2;
    reg  [20:0] ed$0;
    reg  [20:0] ed$1;
    reg  [20:0] ed$2;
    reg  [33:0] pa$0;
    reg  [33:0] pa$1;
    reg  [57:0] pn$0;
    reg  [57:0] pn$1;
    reg  [57:0] pn$2;
    reg  [57:0] pn$3;
    reg  [57:0] pn$4;
    reg  [57:0] pn$5;
    reg  [56:0] pe$0;
    reg  [56:0] pe$1;
    reg  [56:0] pe$2;
    reg  [56:0] pe$3;
    reg  [56:0] pg$0;
    reg  [56:0] pg$1;
    reg  [56:0] pg$2;
    reg  [56:0] pg$3;
    reg  [56:0] pg$4;
    reg  [56:0] pg$5;
    reg  [56:0] pg$6;
    reg  [56:0] pg$7;
    reg  [56:0] pg$8;
    reg  [56:0] pg$9;
    reg  [56:0] pg$10;
    reg  [56:0] pg$11;
    reg  [56:0] pg$12;
    reg  [56:0] pg$13;
    reg  [56:0] pg$14;
    reg  [56:0] pg$15;
    reg  [39:0] ps$0;
    reg  [39:0] ps$1;
    reg  [39:0] ps$2;
    reg  [39:0] ps$3;
    reg  [39:0] ps$4;
    reg  [39:0] ps$5;
    reg  [39:0] ps$6;
    reg  [39:0] ps$7;
    reg  [39:0] ps$8;
    reg  [39:0] ps$9;
    reg  [39:0] ps$10;
    reg  [39:0] ps$11;
    reg  [39:0] ps$12;
    reg  [39:0] ps$13;
    reg  [39:0] ps$14;
    reg  [39:0] ps$15;
    reg  [39:0] ps$16;
    reg  [39:0] ps$17;
    reg  [39:0] ps$18;
    reg  [39:0] ps$19;
    reg  [39:0] ps$20;
    reg  [39:0] ps$21;
    reg  [39:0] ps$22;
    reg  [39:0] ps$23;
    reg  [39:0] ps$24;
    reg  [39:0] ps$25;
    reg  [39:0] ps$26;
    reg  [39:0] ps$27;
    reg  [39:0] ps$28;
    reg  [39:0] ps$29;
    reg  [39:0] ps$30;
    reg  [39:0] ps$31;
    reg  [39:0] ps$32;
    reg  [39:0] ps$33;
    reg  [39:0] ps$34;
    reg  [39:0] ps$35;
    reg  [18:0] delta$0;
    reg  [18:0] delta$1;
    reg  [18:0] delta$2;
    reg  [18:0] delta$3;
    reg  [18:0] delta$4;
    reg  [18:0] delta$5;
    reg  [18:0] delta$6;
    reg  [18:0] delta$7;
    reg  [18:0] delta$8;
    reg  [18:0] delta$9;
    reg  [18:0] delta$10;
    reg  [18:0] delta$11;
    reg  [18:0] delta$12;
    reg  [18:0] delta$13;
    reg  [18:0] delta$14;
    reg  [18:0] delta$15;
    reg  [18:0] delta$16;
    reg  [18:0] delta$17;
    reg  [18:0] delta$18;
    reg  [18:0] delta$19;
    reg  [18:0] delta$20;
    reg  [18:0] delta$21;
    reg  [18:0] delta$22;
    reg  [18:0] delta$23;
    reg  [18:0] eq_b$0;
    reg  [18:0] eq_b$1;
    reg  [18:0] eq_b$2;
    reg  [18:0] eq_b$3;
    reg  [18:0] eq_b$4;
    reg  [18:0] eq_b$5;
    reg  [18:0] eq_b$6;
    reg  [18:0] eq_b$7;
    reg  [18:0] eq_b$8;
    reg  [18:0] eq_b$9;
    reg  [18:0] eq_b$10;
    reg  [18:0] eq_b$11;
    reg  [18:0] eq_b$12;
    reg  [18:0] eq_b$13;
    reg  [18:0] eq_b$14;
    reg  [18:0] eq_b$15;
    reg  [18:0] eq_b$16;
    reg  [18:0] eq_b$17;
    reg  [18:0] eq_b$18;
    reg  [18:0] eq_b$19;
    reg  [18:0] eq_b$20;
    reg  [18:0] eq_b$21;
    reg  [18:0] eq_b$22;
    reg  [18:0] eq_b$23;
    reg  [18:0] op_e$0;
    reg  [18:0] op_e$1;
    reg  [18:0] op_e$2;
    reg  [18:0] op_e$3;
    reg  [18:0] op_g$0;
    reg  [18:0] op_g$1;
    reg  [18:0] op_g$2;
    reg  [18:0] op_g$3;
    reg  [18:0] op_g$4;
    reg  [18:0] op_g$5;
    reg  [18:0] op_g$6;
    reg  [18:0] op_g$7;
    reg  [18:0] op_g$8;
    reg  [18:0] op_g$9;
    reg  [18:0] op_g$10;
    reg  [18:0] op_g$11;
    reg  [18:0] op_g$12;
    reg  [18:0] op_g$13;
    reg  [18:0] op_g$14;
    reg  [18:0] op_g$15;
    reg  [18:0] op_s$0;
    reg  [18:0] op_s$1;
    reg  [18:0] op_s$2;
    reg  [18:0] op_s$3;
    reg  [18:0] op_s$4;
    reg  [18:0] op_s$5;
    reg  [18:0] op_s$6;
    reg  [18:0] op_s$7;
    reg  [18:0] op_s$8;
    reg  [18:0] op_s$9;
    reg  [18:0] op_s$10;
    reg  [18:0] op_s$11;
    reg  [18:0] op_s$12;
    reg  [18:0] op_s$13;
    reg  [18:0] op_s$14;
    reg  [18:0] op_s$15;
    reg  [18:0] op_s$16;
    reg  [18:0] op_s$17;
    reg  [18:0] op_s$18;
    reg  [18:0] op_s$19;
    reg  [18:0] op_s$20;
    reg  [18:0] op_s$21;
    reg  [18:0] op_s$22;
    reg  [18:0] op_s$23;
    reg  [18:0] op_q$0;
    reg  [18:0] op_q$1;
    reg  [18:0] op_q$2;
    reg  [18:0] op_q$3;
    reg  [18:0] op_q$4;
    reg  [18:0] op_q$5;
    reg  [18:0] op_q$6;
    reg  [18:0] op_q$7;
    reg  [18:0] op_q$8;
    reg  [18:0] op_q$9;
    reg  [18:0] op_q$10;
    reg  [18:0] op_q$11;
    reg  [39:0] attr0$0;
    reg  [39:0] attr0$1;
    reg  [39:0] attr0$2;
    reg  [39:0] attr0$3;
    reg  [56:0] shr$0;
    reg  [56:0] shr$1;
    reg  [56:0] shr$2;
    reg  [56:0] shr$3;
    reg  [5:0] lsh;
    reg  [33:0] area_base;
    reg  [57:0] num_base$0;
    reg  [57:0] num_base$1;
    reg  [57:0] num_base$2;
    reg  [56:0] gx_base$0;
    reg  [56:0] gx_base$1;
    reg  [56:0] gx_base$2;
    reg  [56:0] gx_base$3;
    reg  [56:0] gy_base$0;
    reg  [56:0] gy_base$1;
    reg  [56:0] gy_base$2;
    reg  [56:0] gy_base$3;
    reg  [39:0] plane_base$0;
    reg  [39:0] plane_base$1;
    reg  [39:0] plane_base$2;
    reg  [39:0] plane_base$3;
    reg  [39:0] plane_base$4;
    reg  [39:0] plane_base$5;
    reg  [39:0] plane_base$6;
    reg  [39:0] plane_base$7;
    reg  [39:0] plane_base$8;
    reg  [39:0] plane_base$9;
    reg  [39:0] plane_base$10;
    reg  [39:0] plane_base$11;
    reg  [56:0] ddx$0;
    reg  [56:0] ddx$1;
    reg  [56:0] ddx$2;
    reg  [56:0] ddx$3;
    reg  [56:0] ddy$0;
    reg  [56:0] ddy$1;
    reg  [56:0] ddy$2;
    reg  [56:0] ddy$3;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$mul$0 mul$0(
        .clock(mul$0$clock),
        .en(mul$0$en),
        .a(mul$0$a),
        .b(mul$0$b),
        .p(mul$0$p)
    );
    raster_top$fragments$core$triangle_setup$mul$1 mul$1(
        .clock(mul$1$clock),
        .en(mul$1$en),
        .a(mul$1$a),
        .b(mul$1$b),
        .p(mul$1$p)
    );
    raster_top$fragments$core$triangle_setup$mul$2 mul$2(
        .clock(mul$2$clock),
        .en(mul$2$en),
        .a(mul$2$a),
        .b(mul$2$b),
        .p(mul$2$p)
    );
    raster_top$fragments$core$triangle_setup$mul$3 mul$3(
        .clock(mul$3$clock),
        .en(mul$3$en),
        .a(mul$3$a),
        .b(mul$3$b),
        .p(mul$3$p)
    );
    raster_top$fragments$core$triangle_setup$mul$4 mul$4(
        .clock(mul$4$clock),
        .en(mul$4$en),
        .a(mul$4$a),
        .b(mul$4$b),
        .p(mul$4$p)
    );
    raster_top$fragments$core$triangle_setup$mul$5 mul$5(
        .clock(mul$5$clock),
        .en(mul$5$en),
        .a(mul$5$a),
        .b(mul$5$b),
        .p(mul$5$p)
    );
    raster_top$fragments$core$triangle_setup$mul$6 mul$6(
        .clock(mul$6$clock),
        .en(mul$6$en),
        .a(mul$6$a),
        .b(mul$6$b),
        .p(mul$6$p)
    );
    raster_top$fragments$core$triangle_setup$div div(
        .clock(div$clock),
        .inp_valid(div$inp_valid),
        .inp_ready(div$inp_ready),
        .hold(div$hold),
        .inp_n(div$inp_n),
        .inp_d(div$inp_d),
        .out_valid(div$out_valid),
        .out_ready(div$out_ready),
        .out_q(div$out_q),
        .out_r(div$out_r)
    );
    raster_top$fragments$core$triangle_setup$stall_r stall_r(
        .d(stall_r$d),
        .q(stall_r$q),
        .clock(stall_r$clock)
    );
    raster_top$fragments$core$triangle_setup$tok$0 tok$0(
        .d(tok$0$d),
        .q(tok$0$q),
        .clock(tok$0$clock)
    );
    raster_top$fragments$core$triangle_setup$tok$1 tok$1(
        .d(tok$1$d),
        .q(tok$1$q),
        .clock(tok$1$clock)
    );
    raster_top$fragments$core$triangle_setup$tok$2 tok$2(
        .d(tok$2$d),
        .q(tok$2$q),
        .clock(tok$2$clock)
    );
    raster_top$fragments$core$triangle_setup$tok$3 tok$3(
        .d(tok$3$d),
        .q(tok$3$q),
        .clock(tok$3$clock)
    );
    raster_top$fragments$core$triangle_setup$tok$4 tok$4(
        .d(tok$4$d),
        .q(tok$4$q),
        .clock(tok$4$clock)
    );
    raster_top$fragments$core$triangle_setup$tok$5 tok$5(
        .d(tok$5$d),
        .q(tok$5$q),
        .clock(tok$5$clock)
    );
    raster_top$fragments$core$triangle_setup$busy_r busy_r(
        .d(busy_r$d),
        .q(busy_r$q),
        .clock(busy_r$clock)
    );
    raster_top$fragments$core$triangle_setup$gate_r gate_r(
        .d(gate_r$d),
        .q(gate_r$q),
        .clock(gate_r$clock)
    );
    raster_top$fragments$core$triangle_setup$phase phase(
        .d(phase$d),
        .q(phase$q),
        .clock(phase$clock)
    );
    raster_top$fragments$core$triangle_setup$off_grid_r off_grid_r(
        .d(off_grid_r$d),
        .q(off_grid_r$q),
        .clock(off_grid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$geometry geometry(
        .vx$0(geometry$vx$0),
        .vx$1(geometry$vx$1),
        .vx$2(geometry$vx$2),
        .vy$0(geometry$vy$0),
        .vy$1(geometry$vy$1),
        .vy$2(geometry$vy$2),
        .vz$0(geometry$vz$0),
        .vz$1(geometry$vz$1),
        .vz$2(geometry$vz$2),
        .vc$0(geometry$vc$0),
        .vc$1(geometry$vc$1),
        .vc$2(geometry$vc$2),
        .vc$3(geometry$vc$3),
        .vc$4(geometry$vc$4),
        .vc$5(geometry$vc$5),
        .vc$6(geometry$vc$6),
        .vc$7(geometry$vc$7),
        .vc$8(geometry$vc$8),
        .crosses(geometry$crosses),
        .word(geometry$word)
    );
    raster_top$fragments$core$triangle_setup$geo$0 geo$0(
        .d(geo$0$d),
        .q(geo$0$q),
        .clock(geo$0$clock)
    );
    raster_top$fragments$core$triangle_setup$geo$1 geo$1(
        .d(geo$1$d),
        .q(geo$1$q),
        .clock(geo$1$clock)
    );
    raster_top$fragments$core$triangle_setup$geo$2 geo$2(
        .d(geo$2$d),
        .q(geo$2$q),
        .clock(geo$2$clock)
    );
    raster_top$fragments$core$triangle_setup$geo$3 geo$3(
        .d(geo$3$d),
        .q(geo$3$q),
        .clock(geo$3$clock)
    );
    raster_top$fragments$core$triangle_setup$geo$4 geo$4(
        .d(geo$4$d),
        .q(geo$4$q),
        .clock(geo$4$clock)
    );
    raster_top$fragments$core$triangle_setup$geo$5 geo$5(
        .d(geo$5$d),
        .q(geo$5$q),
        .clock(geo$5$clock)
    );
    raster_top$fragments$core$triangle_setup$sign$0 sign$0(
        .d(sign$0$d),
        .q(sign$0$q),
        .clock(sign$0$clock)
    );
    raster_top$fragments$core$triangle_setup$sign$1 sign$1(
        .d(sign$1$d),
        .q(sign$1$q),
        .clock(sign$1$clock)
    );
    raster_top$fragments$core$triangle_setup$sign$2 sign$2(
        .d(sign$2$d),
        .q(sign$2$q),
        .clock(sign$2$clock)
    );
    raster_top$fragments$core$triangle_setup$sign$3 sign$3(
        .d(sign$3$d),
        .q(sign$3$q),
        .clock(sign$3$clock)
    );
    raster_top$fragments$core$triangle_setup$sign$4 sign$4(
        .d(sign$4$d),
        .q(sign$4$q),
        .clock(sign$4$clock)
    );
    raster_top$fragments$core$triangle_setup$sign$5 sign$5(
        .d(sign$5$d),
        .q(sign$5$q),
        .clock(sign$5$clock)
    );
    raster_top$fragments$core$triangle_setup$exp$0 exp$0(
        .d(exp$0$d),
        .q(exp$0$q),
        .clock(exp$0$clock)
    );
    raster_top$fragments$core$triangle_setup$exp$1 exp$1(
        .d(exp$1$d),
        .q(exp$1$q),
        .clock(exp$1$clock)
    );
    raster_top$fragments$core$triangle_setup$exp$2 exp$2(
        .d(exp$2$d),
        .q(exp$2$q),
        .clock(exp$2$clock)
    );
    raster_top$fragments$core$triangle_setup$exp$3 exp$3(
        .d(exp$3$d),
        .q(exp$3$q),
        .clock(exp$3$clock)
    );
    raster_top$fragments$core$triangle_setup$exp$4 exp$4(
        .d(exp$4$d),
        .q(exp$4$q),
        .clock(exp$4$clock)
    );
    raster_top$fragments$core$triangle_setup$exp$5 exp$5(
        .d(exp$5$d),
        .q(exp$5$q),
        .clock(exp$5$clock)
    );
    raster_top$fragments$core$triangle_setup$mant$0 mant$0(
        .d(mant$0$d),
        .q(mant$0$q),
        .clock(mant$0$clock)
    );
    raster_top$fragments$core$triangle_setup$mant$1 mant$1(
        .d(mant$1$d),
        .q(mant$1$q),
        .clock(mant$1$clock)
    );
    raster_top$fragments$core$triangle_setup$mant$2 mant$2(
        .d(mant$2$d),
        .q(mant$2$q),
        .clock(mant$2$clock)
    );
    raster_top$fragments$core$triangle_setup$mant$3 mant$3(
        .d(mant$3$d),
        .q(mant$3$q),
        .clock(mant$3$clock)
    );
    raster_top$fragments$core$triangle_setup$mant$4 mant$4(
        .d(mant$4$d),
        .q(mant$4$q),
        .clock(mant$4$clock)
    );
    raster_top$fragments$core$triangle_setup$mant$5 mant$5(
        .d(mant$5$d),
        .q(mant$5$q),
        .clock(mant$5$clock)
    );
    raster_top$fragments$core$triangle_setup$x$0 x$0(
        .d(x$0$d),
        .q(x$0$q),
        .clock(x$0$clock)
    );
    raster_top$fragments$core$triangle_setup$x$1 x$1(
        .d(x$1$d),
        .q(x$1$q),
        .clock(x$1$clock)
    );
    raster_top$fragments$core$triangle_setup$x$2 x$2(
        .d(x$2$d),
        .q(x$2$q),
        .clock(x$2$clock)
    );
    raster_top$fragments$core$triangle_setup$x$3 x$3(
        .d(x$3$d),
        .q(x$3$q),
        .clock(x$3$clock)
    );
    raster_top$fragments$core$triangle_setup$x$4 x$4(
        .d(x$4$d),
        .q(x$4$q),
        .clock(x$4$clock)
    );
    raster_top$fragments$core$triangle_setup$x$5 x$5(
        .d(x$5$d),
        .q(x$5$q),
        .clock(x$5$clock)
    );
    raster_top$fragments$core$triangle_setup$x$6 x$6(
        .d(x$6$d),
        .q(x$6$q),
        .clock(x$6$clock)
    );
    raster_top$fragments$core$triangle_setup$x$7 x$7(
        .d(x$7$d),
        .q(x$7$q),
        .clock(x$7$clock)
    );
    raster_top$fragments$core$triangle_setup$x$8 x$8(
        .d(x$8$d),
        .q(x$8$q),
        .clock(x$8$clock)
    );
    raster_top$fragments$core$triangle_setup$x$9 x$9(
        .d(x$9$d),
        .q(x$9$q),
        .clock(x$9$clock)
    );
    raster_top$fragments$core$triangle_setup$x$10 x$10(
        .d(x$10$d),
        .q(x$10$q),
        .clock(x$10$clock)
    );
    raster_top$fragments$core$triangle_setup$x$11 x$11(
        .d(x$11$d),
        .q(x$11$q),
        .clock(x$11$clock)
    );
    raster_top$fragments$core$triangle_setup$x$12 x$12(
        .d(x$12$d),
        .q(x$12$q),
        .clock(x$12$clock)
    );
    raster_top$fragments$core$triangle_setup$x$13 x$13(
        .d(x$13$d),
        .q(x$13$q),
        .clock(x$13$clock)
    );
    raster_top$fragments$core$triangle_setup$x$14 x$14(
        .d(x$14$d),
        .q(x$14$q),
        .clock(x$14$clock)
    );
    raster_top$fragments$core$triangle_setup$x$15 x$15(
        .d(x$15$d),
        .q(x$15$q),
        .clock(x$15$clock)
    );
    raster_top$fragments$core$triangle_setup$x$16 x$16(
        .d(x$16$d),
        .q(x$16$q),
        .clock(x$16$clock)
    );
    raster_top$fragments$core$triangle_setup$x$17 x$17(
        .d(x$17$d),
        .q(x$17$q),
        .clock(x$17$clock)
    );
    raster_top$fragments$core$triangle_setup$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    raster_top$fragments$core$triangle_setup$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
    );
    raster_top$fragments$core$triangle_setup$r$2 r$2(
        .d(r$2$d),
        .q(r$2$q),
        .clock(r$2$clock)
    );
    raster_top$fragments$core$triangle_setup$r$3 r$3(
        .d(r$3$d),
        .q(r$3$q),
        .clock(r$3$clock)
    );
    raster_top$fragments$core$triangle_setup$r$4 r$4(
        .d(r$4$d),
        .q(r$4$q),
        .clock(r$4$clock)
    );
    raster_top$fragments$core$triangle_setup$r$5 r$5(
        .d(r$5$d),
        .q(r$5$q),
        .clock(r$5$clock)
    );
    raster_top$fragments$core$triangle_setup$r$6 r$6(
        .d(r$6$d),
        .q(r$6$q),
        .clock(r$6$clock)
    );
    raster_top$fragments$core$triangle_setup$r$7 r$7(
        .d(r$7$d),
        .q(r$7$q),
        .clock(r$7$clock)
    );
    raster_top$fragments$core$triangle_setup$r$8 r$8(
        .d(r$8$d),
        .q(r$8$q),
        .clock(r$8$clock)
    );
    raster_top$fragments$core$triangle_setup$r$9 r$9(
        .d(r$9$d),
        .q(r$9$q),
        .clock(r$9$clock)
    );
    raster_top$fragments$core$triangle_setup$r$10 r$10(
        .d(r$10$d),
        .q(r$10$q),
        .clock(r$10$clock)
    );
    raster_top$fragments$core$triangle_setup$r$11 r$11(
        .d(r$11$d),
        .q(r$11$q),
        .clock(r$11$clock)
    );
    raster_top$fragments$core$triangle_setup$r$12 r$12(
        .d(r$12$d),
        .q(r$12$q),
        .clock(r$12$clock)
    );
    raster_top$fragments$core$triangle_setup$r$13 r$13(
        .d(r$13$d),
        .q(r$13$q),
        .clock(r$13$clock)
    );
    raster_top$fragments$core$triangle_setup$r$14 r$14(
        .d(r$14$d),
        .q(r$14$q),
        .clock(r$14$clock)
    );
    raster_top$fragments$core$triangle_setup$r$15 r$15(
        .d(r$15$d),
        .q(r$15$q),
        .clock(r$15$clock)
    );
    raster_top$fragments$core$triangle_setup$r$16 r$16(
        .d(r$16$d),
        .q(r$16$q),
        .clock(r$16$clock)
    );
    raster_top$fragments$core$triangle_setup$r$17 r$17(
        .d(r$17$d),
        .q(r$17$q),
        .clock(r$17$clock)
    );
    raster_top$fragments$core$triangle_setup$q$0 q$0(
        .d(q$0$d),
        .q(q$0$q),
        .clock(q$0$clock)
    );
    raster_top$fragments$core$triangle_setup$q$1 q$1(
        .d(q$1$d),
        .q(q$1$q),
        .clock(q$1$clock)
    );
    raster_top$fragments$core$triangle_setup$q$2 q$2(
        .d(q$2$d),
        .q(q$2$q),
        .clock(q$2$clock)
    );
    raster_top$fragments$core$triangle_setup$q$3 q$3(
        .d(q$3$d),
        .q(q$3$q),
        .clock(q$3$clock)
    );
    raster_top$fragments$core$triangle_setup$q$4 q$4(
        .d(q$4$d),
        .q(q$4$q),
        .clock(q$4$clock)
    );
    raster_top$fragments$core$triangle_setup$q$5 q$5(
        .d(q$5$d),
        .q(q$5$q),
        .clock(q$5$clock)
    );
    raster_top$fragments$core$triangle_setup$q$6 q$6(
        .d(q$6$d),
        .q(q$6$q),
        .clock(q$6$clock)
    );
    raster_top$fragments$core$triangle_setup$q$7 q$7(
        .d(q$7$d),
        .q(q$7$q),
        .clock(q$7$clock)
    );
    raster_top$fragments$core$triangle_setup$q$8 q$8(
        .d(q$8$d),
        .q(q$8$q),
        .clock(q$8$clock)
    );
    raster_top$fragments$core$triangle_setup$q$9 q$9(
        .d(q$9$d),
        .q(q$9$q),
        .clock(q$9$clock)
    );
    raster_top$fragments$core$triangle_setup$q$10 q$10(
        .d(q$10$d),
        .q(q$10$q),
        .clock(q$10$clock)
    );
    raster_top$fragments$core$triangle_setup$q$11 q$11(
        .d(q$11$d),
        .q(q$11$q),
        .clock(q$11$clock)
    );
    raster_top$fragments$core$triangle_setup$q$12 q$12(
        .d(q$12$d),
        .q(q$12$q),
        .clock(q$12$clock)
    );
    raster_top$fragments$core$triangle_setup$q$13 q$13(
        .d(q$13$d),
        .q(q$13$q),
        .clock(q$13$clock)
    );
    raster_top$fragments$core$triangle_setup$q$14 q$14(
        .d(q$14$d),
        .q(q$14$q),
        .clock(q$14$clock)
    );
    raster_top$fragments$core$triangle_setup$q$15 q$15(
        .d(q$15$d),
        .q(q$15$q),
        .clock(q$15$clock)
    );
    raster_top$fragments$core$triangle_setup$q$16 q$16(
        .d(q$16$d),
        .q(q$16$q),
        .clock(q$16$clock)
    );
    raster_top$fragments$core$triangle_setup$q$17 q$17(
        .d(q$17$d),
        .q(q$17$q),
        .clock(q$17$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$0 rho$0(
        .d(rho$0$d),
        .q(rho$0$q),
        .clock(rho$0$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$1 rho$1(
        .d(rho$1$d),
        .q(rho$1$q),
        .clock(rho$1$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$2 rho$2(
        .d(rho$2$d),
        .q(rho$2$q),
        .clock(rho$2$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$3 rho$3(
        .d(rho$3$d),
        .q(rho$3$q),
        .clock(rho$3$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$4 rho$4(
        .d(rho$4$d),
        .q(rho$4$q),
        .clock(rho$4$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$5 rho$5(
        .d(rho$5$d),
        .q(rho$5$q),
        .clock(rho$5$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$6 rho$6(
        .d(rho$6$d),
        .q(rho$6$q),
        .clock(rho$6$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$7 rho$7(
        .d(rho$7$d),
        .q(rho$7$q),
        .clock(rho$7$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$8 rho$8(
        .d(rho$8$d),
        .q(rho$8$q),
        .clock(rho$8$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$9 rho$9(
        .d(rho$9$d),
        .q(rho$9$q),
        .clock(rho$9$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$10 rho$10(
        .d(rho$10$d),
        .q(rho$10$q),
        .clock(rho$10$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$11 rho$11(
        .d(rho$11$d),
        .q(rho$11$q),
        .clock(rho$11$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$12 rho$12(
        .d(rho$12$d),
        .q(rho$12$q),
        .clock(rho$12$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$13 rho$13(
        .d(rho$13$d),
        .q(rho$13$q),
        .clock(rho$13$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$14 rho$14(
        .d(rho$14$d),
        .q(rho$14$q),
        .clock(rho$14$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$15 rho$15(
        .d(rho$15$d),
        .q(rho$15$q),
        .clock(rho$15$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$16 rho$16(
        .d(rho$16$d),
        .q(rho$16$q),
        .clock(rho$16$clock)
    );
    raster_top$fragments$core$triangle_setup$rho$17 rho$17(
        .d(rho$17$d),
        .q(rho$17$q),
        .clock(rho$17$clock)
    );
    raster_top$fragments$core$triangle_setup$g0 g0(
        .word(g0$word),
        .maj_left(g0$maj_left),
        .start_x$0(g0$start_x$0),
        .start_x$1(g0$start_x$1),
        .start_x$2(g0$start_x$2),
        .kdx$0(g0$kdx$0),
        .kdx$1(g0$kdx$1),
        .kdx$2(g0$kdx$2),
        .kdy$0(g0$kdy$0),
        .kdy$1(g0$kdy$1),
        .kdy$2(g0$kdy$2),
        .up(g0$up),
        .edx$0(g0$edx$0),
        .edx$1(g0$edx$1),
        .edx$2(g0$edx$2),
        .edy$0(g0$edy$0),
        .edy$1(g0$edy$1),
        .edy$2(g0$edy$2),
        .edy_d$0(g0$edy_d$0),
        .edy_d$1(g0$edy_d$1),
        .edy_d$2(g0$edy_d$2),
        .ed16$0(g0$ed16$0),
        .ed16$1(g0$ed16$1),
        .ed16$2(g0$ed16$2),
        .cy$0(g0$cy$0),
        .cy$1(g0$cy$1),
        .cy$2(g0$cy$2),
        .count$0(g0$count$0),
        .count$1(g0$count$1),
        .count$2(g0$count$2),
        .used$0(g0$used$0),
        .used$1(g0$used$1),
        .used$2(g0$used$2),
        .step$0(g0$step$0),
        .step$1(g0$step$1),
        .step$2(g0$step$2),
        .toff$0(g0$toff$0),
        .toff$1(g0$toff$1),
        .toff$2(g0$toff$2),
        .xf$0(g0$xf$0),
        .xf$1(g0$xf$1),
        .xf$2(g0$xf$2),
        .xi$0(g0$xi$0),
        .xi$1(g0$xi$1),
        .xi$2(g0$xi$2),
        .off_x$0(g0$off_x$0),
        .off_x$1(g0$off_x$1),
        .off_x$2(g0$off_x$2),
        .off_y$0(g0$off_y$0),
        .off_y$1(g0$off_y$1),
        .off_y$2(g0$off_y$2),
        .dmaj$0(g0$dmaj$0),
        .dmaj$1(g0$dmaj$1),
        .dmaj$2(g0$dmaj$2),
        .dmaj$3(g0$dmaj$3),
        .dbot$0(g0$dbot$0),
        .dbot$1(g0$dbot$1),
        .dbot$2(g0$dbot$2),
        .dbot$3(g0$dbot$3),
        .attr0$0(g0$attr0$0),
        .attr0$1(g0$attr0$1),
        .attr0$2(g0$attr0$2),
        .attr0$3(g0$attr0$3)
    );
    raster_top$fragments$core$triangle_setup$g1 g1(
        .word(g1$word),
        .maj_left(g1$maj_left),
        .start_x$0(g1$start_x$0),
        .start_x$1(g1$start_x$1),
        .start_x$2(g1$start_x$2),
        .kdx$0(g1$kdx$0),
        .kdx$1(g1$kdx$1),
        .kdx$2(g1$kdx$2),
        .kdy$0(g1$kdy$0),
        .kdy$1(g1$kdy$1),
        .kdy$2(g1$kdy$2),
        .up(g1$up),
        .edx$0(g1$edx$0),
        .edx$1(g1$edx$1),
        .edx$2(g1$edx$2),
        .edy$0(g1$edy$0),
        .edy$1(g1$edy$1),
        .edy$2(g1$edy$2),
        .edy_d$0(g1$edy_d$0),
        .edy_d$1(g1$edy_d$1),
        .edy_d$2(g1$edy_d$2),
        .ed16$0(g1$ed16$0),
        .ed16$1(g1$ed16$1),
        .ed16$2(g1$ed16$2),
        .cy$0(g1$cy$0),
        .cy$1(g1$cy$1),
        .cy$2(g1$cy$2),
        .count$0(g1$count$0),
        .count$1(g1$count$1),
        .count$2(g1$count$2),
        .used$0(g1$used$0),
        .used$1(g1$used$1),
        .used$2(g1$used$2),
        .step$0(g1$step$0),
        .step$1(g1$step$1),
        .step$2(g1$step$2),
        .toff$0(g1$toff$0),
        .toff$1(g1$toff$1),
        .toff$2(g1$toff$2),
        .xf$0(g1$xf$0),
        .xf$1(g1$xf$1),
        .xf$2(g1$xf$2),
        .xi$0(g1$xi$0),
        .xi$1(g1$xi$1),
        .xi$2(g1$xi$2),
        .off_x$0(g1$off_x$0),
        .off_x$1(g1$off_x$1),
        .off_x$2(g1$off_x$2),
        .off_y$0(g1$off_y$0),
        .off_y$1(g1$off_y$1),
        .off_y$2(g1$off_y$2),
        .dmaj$0(g1$dmaj$0),
        .dmaj$1(g1$dmaj$1),
        .dmaj$2(g1$dmaj$2),
        .dmaj$3(g1$dmaj$3),
        .dbot$0(g1$dbot$0),
        .dbot$1(g1$dbot$1),
        .dbot$2(g1$dbot$2),
        .dbot$3(g1$dbot$3),
        .attr0$0(g1$attr0$0),
        .attr0$1(g1$attr0$1),
        .attr0$2(g1$attr0$2),
        .attr0$3(g1$attr0$3)
    );
    raster_top$fragments$core$triangle_setup$g2 g2(
        .word(g2$word),
        .maj_left(g2$maj_left),
        .start_x$0(g2$start_x$0),
        .start_x$1(g2$start_x$1),
        .start_x$2(g2$start_x$2),
        .kdx$0(g2$kdx$0),
        .kdx$1(g2$kdx$1),
        .kdx$2(g2$kdx$2),
        .kdy$0(g2$kdy$0),
        .kdy$1(g2$kdy$1),
        .kdy$2(g2$kdy$2),
        .up(g2$up),
        .edx$0(g2$edx$0),
        .edx$1(g2$edx$1),
        .edx$2(g2$edx$2),
        .edy$0(g2$edy$0),
        .edy$1(g2$edy$1),
        .edy$2(g2$edy$2),
        .edy_d$0(g2$edy_d$0),
        .edy_d$1(g2$edy_d$1),
        .edy_d$2(g2$edy_d$2),
        .ed16$0(g2$ed16$0),
        .ed16$1(g2$ed16$1),
        .ed16$2(g2$ed16$2),
        .cy$0(g2$cy$0),
        .cy$1(g2$cy$1),
        .cy$2(g2$cy$2),
        .count$0(g2$count$0),
        .count$1(g2$count$1),
        .count$2(g2$count$2),
        .used$0(g2$used$0),
        .used$1(g2$used$1),
        .used$2(g2$used$2),
        .step$0(g2$step$0),
        .step$1(g2$step$1),
        .step$2(g2$step$2),
        .toff$0(g2$toff$0),
        .toff$1(g2$toff$1),
        .toff$2(g2$toff$2),
        .xf$0(g2$xf$0),
        .xf$1(g2$xf$1),
        .xf$2(g2$xf$2),
        .xi$0(g2$xi$0),
        .xi$1(g2$xi$1),
        .xi$2(g2$xi$2),
        .off_x$0(g2$off_x$0),
        .off_x$1(g2$off_x$1),
        .off_x$2(g2$off_x$2),
        .off_y$0(g2$off_y$0),
        .off_y$1(g2$off_y$1),
        .off_y$2(g2$off_y$2),
        .dmaj$0(g2$dmaj$0),
        .dmaj$1(g2$dmaj$1),
        .dmaj$2(g2$dmaj$2),
        .dmaj$3(g2$dmaj$3),
        .dbot$0(g2$dbot$0),
        .dbot$1(g2$dbot$1),
        .dbot$2(g2$dbot$2),
        .dbot$3(g2$dbot$3),
        .attr0$0(g2$attr0$0),
        .attr0$1(g2$attr0$1),
        .attr0$2(g2$attr0$2),
        .attr0$3(g2$attr0$3)
    );
    raster_top$fragments$core$triangle_setup$g3 g3(
        .word(g3$word),
        .maj_left(g3$maj_left),
        .start_x$0(g3$start_x$0),
        .start_x$1(g3$start_x$1),
        .start_x$2(g3$start_x$2),
        .kdx$0(g3$kdx$0),
        .kdx$1(g3$kdx$1),
        .kdx$2(g3$kdx$2),
        .kdy$0(g3$kdy$0),
        .kdy$1(g3$kdy$1),
        .kdy$2(g3$kdy$2),
        .up(g3$up),
        .edx$0(g3$edx$0),
        .edx$1(g3$edx$1),
        .edx$2(g3$edx$2),
        .edy$0(g3$edy$0),
        .edy$1(g3$edy$1),
        .edy$2(g3$edy$2),
        .edy_d$0(g3$edy_d$0),
        .edy_d$1(g3$edy_d$1),
        .edy_d$2(g3$edy_d$2),
        .ed16$0(g3$ed16$0),
        .ed16$1(g3$ed16$1),
        .ed16$2(g3$ed16$2),
        .cy$0(g3$cy$0),
        .cy$1(g3$cy$1),
        .cy$2(g3$cy$2),
        .count$0(g3$count$0),
        .count$1(g3$count$1),
        .count$2(g3$count$2),
        .used$0(g3$used$0),
        .used$1(g3$used$1),
        .used$2(g3$used$2),
        .step$0(g3$step$0),
        .step$1(g3$step$1),
        .step$2(g3$step$2),
        .toff$0(g3$toff$0),
        .toff$1(g3$toff$1),
        .toff$2(g3$toff$2),
        .xf$0(g3$xf$0),
        .xf$1(g3$xf$1),
        .xf$2(g3$xf$2),
        .xi$0(g3$xi$0),
        .xi$1(g3$xi$1),
        .xi$2(g3$xi$2),
        .off_x$0(g3$off_x$0),
        .off_x$1(g3$off_x$1),
        .off_x$2(g3$off_x$2),
        .off_y$0(g3$off_y$0),
        .off_y$1(g3$off_y$1),
        .off_y$2(g3$off_y$2),
        .dmaj$0(g3$dmaj$0),
        .dmaj$1(g3$dmaj$1),
        .dmaj$2(g3$dmaj$2),
        .dmaj$3(g3$dmaj$3),
        .dbot$0(g3$dbot$0),
        .dbot$1(g3$dbot$1),
        .dbot$2(g3$dbot$2),
        .dbot$3(g3$dbot$3),
        .attr0$0(g3$attr0$0),
        .attr0$1(g3$attr0$1),
        .attr0$2(g3$attr0$2),
        .attr0$3(g3$attr0$3)
    );
    raster_top$fragments$core$triangle_setup$g4 g4(
        .word(g4$word),
        .maj_left(g4$maj_left),
        .start_x$0(g4$start_x$0),
        .start_x$1(g4$start_x$1),
        .start_x$2(g4$start_x$2),
        .kdx$0(g4$kdx$0),
        .kdx$1(g4$kdx$1),
        .kdx$2(g4$kdx$2),
        .kdy$0(g4$kdy$0),
        .kdy$1(g4$kdy$1),
        .kdy$2(g4$kdy$2),
        .up(g4$up),
        .edx$0(g4$edx$0),
        .edx$1(g4$edx$1),
        .edx$2(g4$edx$2),
        .edy$0(g4$edy$0),
        .edy$1(g4$edy$1),
        .edy$2(g4$edy$2),
        .edy_d$0(g4$edy_d$0),
        .edy_d$1(g4$edy_d$1),
        .edy_d$2(g4$edy_d$2),
        .ed16$0(g4$ed16$0),
        .ed16$1(g4$ed16$1),
        .ed16$2(g4$ed16$2),
        .cy$0(g4$cy$0),
        .cy$1(g4$cy$1),
        .cy$2(g4$cy$2),
        .count$0(g4$count$0),
        .count$1(g4$count$1),
        .count$2(g4$count$2),
        .used$0(g4$used$0),
        .used$1(g4$used$1),
        .used$2(g4$used$2),
        .step$0(g4$step$0),
        .step$1(g4$step$1),
        .step$2(g4$step$2),
        .toff$0(g4$toff$0),
        .toff$1(g4$toff$1),
        .toff$2(g4$toff$2),
        .xf$0(g4$xf$0),
        .xf$1(g4$xf$1),
        .xf$2(g4$xf$2),
        .xi$0(g4$xi$0),
        .xi$1(g4$xi$1),
        .xi$2(g4$xi$2),
        .off_x$0(g4$off_x$0),
        .off_x$1(g4$off_x$1),
        .off_x$2(g4$off_x$2),
        .off_y$0(g4$off_y$0),
        .off_y$1(g4$off_y$1),
        .off_y$2(g4$off_y$2),
        .dmaj$0(g4$dmaj$0),
        .dmaj$1(g4$dmaj$1),
        .dmaj$2(g4$dmaj$2),
        .dmaj$3(g4$dmaj$3),
        .dbot$0(g4$dbot$0),
        .dbot$1(g4$dbot$1),
        .dbot$2(g4$dbot$2),
        .dbot$3(g4$dbot$3),
        .attr0$0(g4$attr0$0),
        .attr0$1(g4$attr0$1),
        .attr0$2(g4$attr0$2),
        .attr0$3(g4$attr0$3)
    );
    raster_top$fragments$core$triangle_setup$g5 g5(
        .word(g5$word),
        .maj_left(g5$maj_left),
        .start_x$0(g5$start_x$0),
        .start_x$1(g5$start_x$1),
        .start_x$2(g5$start_x$2),
        .kdx$0(g5$kdx$0),
        .kdx$1(g5$kdx$1),
        .kdx$2(g5$kdx$2),
        .kdy$0(g5$kdy$0),
        .kdy$1(g5$kdy$1),
        .kdy$2(g5$kdy$2),
        .up(g5$up),
        .edx$0(g5$edx$0),
        .edx$1(g5$edx$1),
        .edx$2(g5$edx$2),
        .edy$0(g5$edy$0),
        .edy$1(g5$edy$1),
        .edy$2(g5$edy$2),
        .edy_d$0(g5$edy_d$0),
        .edy_d$1(g5$edy_d$1),
        .edy_d$2(g5$edy_d$2),
        .ed16$0(g5$ed16$0),
        .ed16$1(g5$ed16$1),
        .ed16$2(g5$ed16$2),
        .cy$0(g5$cy$0),
        .cy$1(g5$cy$1),
        .cy$2(g5$cy$2),
        .count$0(g5$count$0),
        .count$1(g5$count$1),
        .count$2(g5$count$2),
        .used$0(g5$used$0),
        .used$1(g5$used$1),
        .used$2(g5$used$2),
        .step$0(g5$step$0),
        .step$1(g5$step$1),
        .step$2(g5$step$2),
        .toff$0(g5$toff$0),
        .toff$1(g5$toff$1),
        .toff$2(g5$toff$2),
        .xf$0(g5$xf$0),
        .xf$1(g5$xf$1),
        .xf$2(g5$xf$2),
        .xi$0(g5$xi$0),
        .xi$1(g5$xi$1),
        .xi$2(g5$xi$2),
        .off_x$0(g5$off_x$0),
        .off_x$1(g5$off_x$1),
        .off_x$2(g5$off_x$2),
        .off_y$0(g5$off_y$0),
        .off_y$1(g5$off_y$1),
        .off_y$2(g5$off_y$2),
        .dmaj$0(g5$dmaj$0),
        .dmaj$1(g5$dmaj$1),
        .dmaj$2(g5$dmaj$2),
        .dmaj$3(g5$dmaj$3),
        .dbot$0(g5$dbot$0),
        .dbot$1(g5$dbot$1),
        .dbot$2(g5$dbot$2),
        .dbot$3(g5$dbot$3),
        .attr0$0(g5$attr0$0),
        .attr0$1(g5$attr0$1),
        .attr0$2(g5$attr0$2),
        .attr0$3(g5$attr0$3)
    );
    raster_top$fragments$core$triangle_setup$area area(
        .d(area$d),
        .q(area$q),
        .clock(area$clock)
    );
    raster_top$fragments$core$triangle_setup$norm norm(
        .d(norm$d),
        .q(norm$q),
        .clock(norm$clock)
    );
    raster_top$fragments$core$triangle_setup$nsh nsh(
        .d(nsh$d),
        .q(nsh$q),
        .clock(nsh$clock)
    );
    raster_top$fragments$core$triangle_setup$div_v div_v(
        .d(div_v$d),
        .q(div_v$q),
        .clock(div_v$clock)
    );
    raster_top$fragments$core$triangle_setup$div_n div_n(
        .d(div_n$d),
        .q(div_n$q),
        .clock(div_n$clock)
    );
    raster_top$fragments$core$triangle_setup$div_d div_d(
        .d(div_d$d),
        .q(div_d$q),
        .clock(div_d$clock)
    );
    raster_top$fragments$core$triangle_setup$mant_s mant_s(
        .d(mant_s$d),
        .q(mant_s$q),
        .clock(mant_s$clock)
    );
    raster_top$fragments$core$triangle_setup$rsh rsh(
        .d(rsh$d),
        .q(rsh$q),
        .clock(rsh$clock)
    );
    raster_top$fragments$core$triangle_setup$left left(
        .d(left$d),
        .q(left$q),
        .clock(left$clock)
    );
    raster_top$fragments$core$triangle_setup$num$0 num$0(
        .d(num$0$d),
        .q(num$0$q),
        .clock(num$0$clock)
    );
    raster_top$fragments$core$triangle_setup$num$1 num$1(
        .d(num$1$d),
        .q(num$1$q),
        .clock(num$1$clock)
    );
    raster_top$fragments$core$triangle_setup$num$2 num$2(
        .d(num$2$d),
        .q(num$2$q),
        .clock(num$2$clock)
    );
    raster_top$fragments$core$triangle_setup$p$0 p$0(
        .d(p$0$d),
        .q(p$0$q),
        .clock(p$0$clock)
    );
    raster_top$fragments$core$triangle_setup$p$1 p$1(
        .d(p$1$d),
        .q(p$1$q),
        .clock(p$1$clock)
    );
    raster_top$fragments$core$triangle_setup$p$2 p$2(
        .d(p$2$d),
        .q(p$2$q),
        .clock(p$2$clock)
    );
    raster_top$fragments$core$triangle_setup$p$3 p$3(
        .d(p$3$d),
        .q(p$3$q),
        .clock(p$3$clock)
    );
    raster_top$fragments$core$triangle_setup$gx$0 gx$0(
        .d(gx$0$d),
        .q(gx$0$q),
        .clock(gx$0$clock)
    );
    raster_top$fragments$core$triangle_setup$gx$1 gx$1(
        .d(gx$1$d),
        .q(gx$1$q),
        .clock(gx$1$clock)
    );
    raster_top$fragments$core$triangle_setup$gx$2 gx$2(
        .d(gx$2$d),
        .q(gx$2$q),
        .clock(gx$2$clock)
    );
    raster_top$fragments$core$triangle_setup$gx$3 gx$3(
        .d(gx$3$d),
        .q(gx$3$q),
        .clock(gx$3$clock)
    );
    raster_top$fragments$core$triangle_setup$gy$0 gy$0(
        .d(gy$0$d),
        .q(gy$0$q),
        .clock(gy$0$clock)
    );
    raster_top$fragments$core$triangle_setup$gy$1 gy$1(
        .d(gy$1$d),
        .q(gy$1$q),
        .clock(gy$1$clock)
    );
    raster_top$fragments$core$triangle_setup$gy$2 gy$2(
        .d(gy$2$d),
        .q(gy$2$q),
        .clock(gy$2$clock)
    );
    raster_top$fragments$core$triangle_setup$gy$3 gy$3(
        .d(gy$3$d),
        .q(gy$3$q),
        .clock(gy$3$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$0 plane$0(
        .d(plane$0$d),
        .q(plane$0$q),
        .clock(plane$0$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$1 plane$1(
        .d(plane$1$d),
        .q(plane$1$q),
        .clock(plane$1$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$2 plane$2(
        .d(plane$2$d),
        .q(plane$2$q),
        .clock(plane$2$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$3 plane$3(
        .d(plane$3$d),
        .q(plane$3$q),
        .clock(plane$3$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$4 plane$4(
        .d(plane$4$d),
        .q(plane$4$q),
        .clock(plane$4$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$5 plane$5(
        .d(plane$5$d),
        .q(plane$5$q),
        .clock(plane$5$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$6 plane$6(
        .d(plane$6$d),
        .q(plane$6$q),
        .clock(plane$6$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$7 plane$7(
        .d(plane$7$d),
        .q(plane$7$q),
        .clock(plane$7$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$8 plane$8(
        .d(plane$8$d),
        .q(plane$8$q),
        .clock(plane$8$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$9 plane$9(
        .d(plane$9$d),
        .q(plane$9$q),
        .clock(plane$9$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$10 plane$10(
        .d(plane$10$d),
        .q(plane$10$q),
        .clock(plane$10$clock)
    );
    raster_top$fragments$core$triangle_setup$plane$11 plane$11(
        .d(plane$11$d),
        .q(plane$11$q),
        .clock(plane$11$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$0 inc0$0(
        .d(inc0$0$d),
        .q(inc0$0$q),
        .clock(inc0$0$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$1 inc0$1(
        .d(inc0$1$d),
        .q(inc0$1$q),
        .clock(inc0$1$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$2 inc0$2(
        .d(inc0$2$d),
        .q(inc0$2$q),
        .clock(inc0$2$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$3 inc0$3(
        .d(inc0$3$d),
        .q(inc0$3$q),
        .clock(inc0$3$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$4 inc0$4(
        .d(inc0$4$d),
        .q(inc0$4$q),
        .clock(inc0$4$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$5 inc0$5(
        .d(inc0$5$d),
        .q(inc0$5$q),
        .clock(inc0$5$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$6 inc0$6(
        .d(inc0$6$d),
        .q(inc0$6$q),
        .clock(inc0$6$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$7 inc0$7(
        .d(inc0$7$d),
        .q(inc0$7$q),
        .clock(inc0$7$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$8 inc0$8(
        .d(inc0$8$d),
        .q(inc0$8$q),
        .clock(inc0$8$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$9 inc0$9(
        .d(inc0$9$d),
        .q(inc0$9$q),
        .clock(inc0$9$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$10 inc0$10(
        .d(inc0$10$d),
        .q(inc0$10$q),
        .clock(inc0$10$clock)
    );
    raster_top$fragments$core$triangle_setup$inc0$11 inc0$11(
        .d(inc0$11$d),
        .q(inc0$11$q),
        .clock(inc0$11$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$0 inc1$0(
        .d(inc1$0$d),
        .q(inc1$0$q),
        .clock(inc1$0$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$1 inc1$1(
        .d(inc1$1$d),
        .q(inc1$1$q),
        .clock(inc1$1$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$2 inc1$2(
        .d(inc1$2$d),
        .q(inc1$2$q),
        .clock(inc1$2$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$3 inc1$3(
        .d(inc1$3$d),
        .q(inc1$3$q),
        .clock(inc1$3$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$4 inc1$4(
        .d(inc1$4$d),
        .q(inc1$4$q),
        .clock(inc1$4$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$5 inc1$5(
        .d(inc1$5$d),
        .q(inc1$5$q),
        .clock(inc1$5$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$6 inc1$6(
        .d(inc1$6$d),
        .q(inc1$6$q),
        .clock(inc1$6$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$7 inc1$7(
        .d(inc1$7$d),
        .q(inc1$7$q),
        .clock(inc1$7$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$8 inc1$8(
        .d(inc1$8$d),
        .q(inc1$8$q),
        .clock(inc1$8$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$9 inc1$9(
        .d(inc1$9$d),
        .q(inc1$9$q),
        .clock(inc1$9$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$10 inc1$10(
        .d(inc1$10$d),
        .q(inc1$10$q),
        .clock(inc1$10$clock)
    );
    raster_top$fragments$core$triangle_setup$inc1$11 inc1$11(
        .d(inc1$11$d),
        .q(inc1$11$q),
        .clock(inc1$11$clock)
    );
    raster_top$fragments$core$triangle_setup$ddx_o$0 ddx_o$0(
        .d(ddx_o$0$d),
        .q(ddx_o$0$q),
        .clock(ddx_o$0$clock)
    );
    raster_top$fragments$core$triangle_setup$ddx_o$1 ddx_o$1(
        .d(ddx_o$1$d),
        .q(ddx_o$1$q),
        .clock(ddx_o$1$clock)
    );
    raster_top$fragments$core$triangle_setup$ddx_o$2 ddx_o$2(
        .d(ddx_o$2$d),
        .q(ddx_o$2$q),
        .clock(ddx_o$2$clock)
    );
    raster_top$fragments$core$triangle_setup$ddx_o$3 ddx_o$3(
        .d(ddx_o$3$d),
        .q(ddx_o$3$q),
        .clock(ddx_o$3$clock)
    );
    raster_top$fragments$core$triangle_setup$o_walk o_walk(
        .d(o_walk$d),
        .q(o_walk$q),
        .clock(o_walk$clock)
    );
    raster_top$fragments$core$triangle_setup$o_maj_left o_maj_left(
        .d(o_maj_left$d),
        .q(o_maj_left$q),
        .clock(o_maj_left$clock)
    );
    raster_top$fragments$core$triangle_setup$o_j$0 o_j$0(
        .d(o_j$0$d),
        .q(o_j$0$q),
        .clock(o_j$0$clock)
    );
    raster_top$fragments$core$triangle_setup$o_j$1 o_j$1(
        .d(o_j$1$d),
        .q(o_j$1$q),
        .clock(o_j$1$clock)
    );
    raster_top$fragments$core$triangle_setup$o_j$2 o_j$2(
        .d(o_j$2$d),
        .q(o_j$2$q),
        .clock(o_j$2$clock)
    );
    raster_top$fragments$core$triangle_setup$o_count$0 o_count$0(
        .d(o_count$0$d),
        .q(o_count$0$q),
        .clock(o_count$0$clock)
    );
    raster_top$fragments$core$triangle_setup$o_count$1 o_count$1(
        .d(o_count$1$d),
        .q(o_count$1$q),
        .clock(o_count$1$clock)
    );
    raster_top$fragments$core$triangle_setup$o_count$2 o_count$2(
        .d(o_count$2$d),
        .q(o_count$2$q),
        .clock(o_count$2$clock)
    );
    raster_top$fragments$core$triangle_setup$o_d$0 o_d$0(
        .d(o_d$0$d),
        .q(o_d$0$q),
        .clock(o_d$0$clock)
    );
    raster_top$fragments$core$triangle_setup$o_d$1 o_d$1(
        .d(o_d$1$d),
        .q(o_d$1$q),
        .clock(o_d$1$clock)
    );
    raster_top$fragments$core$triangle_setup$o_d$2 o_d$2(
        .d(o_d$2$d),
        .q(o_d$2$q),
        .clock(o_d$2$clock)
    );
    
    // Update code
    always @(*) begin
        area$clock = clock;
        norm$clock = clock;
        nsh$clock = clock;
        div_v$clock = clock;
        div_n$clock = clock;
        div_d$clock = clock;
        mant_s$clock = clock;
        rsh$clock = clock;
        left$clock = clock;
        busy_r$clock = clock;
        gate_r$clock = clock;
        phase$clock = clock;
        off_grid_r$clock = clock;
        stall_r$clock = clock;
        area$d = area$q;
        norm$d = norm$q;
        nsh$d = nsh$q;
        div_v$d = div_v$q;
        div_n$d = div_n$q;
        div_d$d = div_d$q;
        mant_s$d = mant_s$q;
        rsh$d = rsh$q;
        left$d = left$q;
        busy_r$d = busy_r$q;
        gate_r$d = gate_r$q;
        phase$d = phase$q;
        off_grid_r$d = off_grid_r$q;
        stall_r$d = stall_r$q;
        o_walk$clock = clock;
        o_maj_left$clock = clock;
        o_walk$d = o_walk$q;
        o_maj_left$d = o_maj_left$q;
        o_j$0$clock = clock;
        o_j$0$d = o_j$0$q;
        o_count$0$clock = clock;
        o_count$0$d = o_count$0$q;
        o_d$0$clock = clock;
        o_d$0$d = o_d$0$q;
        o_j$1$clock = clock;
        o_j$1$d = o_j$1$q;
        o_count$1$clock = clock;
        o_count$1$d = o_count$1$q;
        o_d$1$clock = clock;
        o_d$1$d = o_d$1$q;
        o_j$2$clock = clock;
        o_j$2$d = o_j$2$q;
        o_count$2$clock = clock;
        o_count$2$d = o_count$2$q;
        o_d$2$clock = clock;
        o_d$2$d = o_d$2$q;
        div$clock = clock;
        tok$0$clock = clock;
        geo$0$clock = clock;
        geo$0$d = geo$0$q;
        sign$0$clock = clock;
        sign$0$d = sign$0$q;
        exp$0$clock = clock;
        exp$0$d = exp$0$q;
        mant$0$clock = clock;
        mant$0$d = mant$0$q;
        x$0$clock = clock;
        x$0$d = x$0$q;
        r$0$clock = clock;
        r$0$d = r$0$q;
        q$0$clock = clock;
        q$0$d = q$0$q;
        rho$0$clock = clock;
        rho$0$d = rho$0$q;
        x$1$clock = clock;
        x$1$d = x$1$q;
        r$1$clock = clock;
        r$1$d = r$1$q;
        q$1$clock = clock;
        q$1$d = q$1$q;
        rho$1$clock = clock;
        rho$1$d = rho$1$q;
        x$2$clock = clock;
        x$2$d = x$2$q;
        r$2$clock = clock;
        r$2$d = r$2$q;
        q$2$clock = clock;
        q$2$d = q$2$q;
        rho$2$clock = clock;
        rho$2$d = rho$2$q;
        tok$1$clock = clock;
        geo$1$clock = clock;
        geo$1$d = geo$1$q;
        sign$1$clock = clock;
        sign$1$d = sign$1$q;
        exp$1$clock = clock;
        exp$1$d = exp$1$q;
        mant$1$clock = clock;
        mant$1$d = mant$1$q;
        x$3$clock = clock;
        x$3$d = x$3$q;
        r$3$clock = clock;
        r$3$d = r$3$q;
        q$3$clock = clock;
        q$3$d = q$3$q;
        rho$3$clock = clock;
        rho$3$d = rho$3$q;
        x$4$clock = clock;
        x$4$d = x$4$q;
        r$4$clock = clock;
        r$4$d = r$4$q;
        q$4$clock = clock;
        q$4$d = q$4$q;
        rho$4$clock = clock;
        rho$4$d = rho$4$q;
        x$5$clock = clock;
        x$5$d = x$5$q;
        r$5$clock = clock;
        r$5$d = r$5$q;
        q$5$clock = clock;
        q$5$d = q$5$q;
        rho$5$clock = clock;
        rho$5$d = rho$5$q;
        tok$2$clock = clock;
        geo$2$clock = clock;
        geo$2$d = geo$2$q;
        sign$2$clock = clock;
        sign$2$d = sign$2$q;
        exp$2$clock = clock;
        exp$2$d = exp$2$q;
        mant$2$clock = clock;
        mant$2$d = mant$2$q;
        x$6$clock = clock;
        x$6$d = x$6$q;
        r$6$clock = clock;
        r$6$d = r$6$q;
        q$6$clock = clock;
        q$6$d = q$6$q;
        rho$6$clock = clock;
        rho$6$d = rho$6$q;
        x$7$clock = clock;
        x$7$d = x$7$q;
        r$7$clock = clock;
        r$7$d = r$7$q;
        q$7$clock = clock;
        q$7$d = q$7$q;
        rho$7$clock = clock;
        rho$7$d = rho$7$q;
        x$8$clock = clock;
        x$8$d = x$8$q;
        r$8$clock = clock;
        r$8$d = r$8$q;
        q$8$clock = clock;
        q$8$d = q$8$q;
        rho$8$clock = clock;
        rho$8$d = rho$8$q;
        tok$3$clock = clock;
        geo$3$clock = clock;
        geo$3$d = geo$3$q;
        sign$3$clock = clock;
        sign$3$d = sign$3$q;
        exp$3$clock = clock;
        exp$3$d = exp$3$q;
        mant$3$clock = clock;
        mant$3$d = mant$3$q;
        x$9$clock = clock;
        x$9$d = x$9$q;
        r$9$clock = clock;
        r$9$d = r$9$q;
        q$9$clock = clock;
        q$9$d = q$9$q;
        rho$9$clock = clock;
        rho$9$d = rho$9$q;
        x$10$clock = clock;
        x$10$d = x$10$q;
        r$10$clock = clock;
        r$10$d = r$10$q;
        q$10$clock = clock;
        q$10$d = q$10$q;
        rho$10$clock = clock;
        rho$10$d = rho$10$q;
        x$11$clock = clock;
        x$11$d = x$11$q;
        r$11$clock = clock;
        r$11$d = r$11$q;
        q$11$clock = clock;
        q$11$d = q$11$q;
        rho$11$clock = clock;
        rho$11$d = rho$11$q;
        tok$4$clock = clock;
        geo$4$clock = clock;
        geo$4$d = geo$4$q;
        sign$4$clock = clock;
        sign$4$d = sign$4$q;
        exp$4$clock = clock;
        exp$4$d = exp$4$q;
        mant$4$clock = clock;
        mant$4$d = mant$4$q;
        x$12$clock = clock;
        x$12$d = x$12$q;
        r$12$clock = clock;
        r$12$d = r$12$q;
        q$12$clock = clock;
        q$12$d = q$12$q;
        rho$12$clock = clock;
        rho$12$d = rho$12$q;
        x$13$clock = clock;
        x$13$d = x$13$q;
        r$13$clock = clock;
        r$13$d = r$13$q;
        q$13$clock = clock;
        q$13$d = q$13$q;
        rho$13$clock = clock;
        rho$13$d = rho$13$q;
        x$14$clock = clock;
        x$14$d = x$14$q;
        r$14$clock = clock;
        r$14$d = r$14$q;
        q$14$clock = clock;
        q$14$d = q$14$q;
        rho$14$clock = clock;
        rho$14$d = rho$14$q;
        tok$5$clock = clock;
        geo$5$clock = clock;
        geo$5$d = geo$5$q;
        sign$5$clock = clock;
        sign$5$d = sign$5$q;
        exp$5$clock = clock;
        exp$5$d = exp$5$q;
        mant$5$clock = clock;
        mant$5$d = mant$5$q;
        x$15$clock = clock;
        x$15$d = x$15$q;
        r$15$clock = clock;
        r$15$d = r$15$q;
        q$15$clock = clock;
        q$15$d = q$15$q;
        rho$15$clock = clock;
        rho$15$d = rho$15$q;
        x$16$clock = clock;
        x$16$d = x$16$q;
        r$16$clock = clock;
        r$16$d = r$16$q;
        q$16$clock = clock;
        q$16$d = q$16$q;
        rho$16$clock = clock;
        rho$16$d = rho$16$q;
        x$17$clock = clock;
        x$17$d = x$17$q;
        r$17$clock = clock;
        r$17$d = r$17$q;
        q$17$clock = clock;
        q$17$d = q$17$q;
        rho$17$clock = clock;
        rho$17$d = rho$17$q;
        num$0$clock = clock;
        num$0$d = num$0$q;
        num$1$clock = clock;
        num$1$d = num$1$q;
        num$2$clock = clock;
        num$2$d = num$2$q;
        p$0$clock = clock;
        p$0$d = p$0$q;
        gx$0$clock = clock;
        gx$0$d = gx$0$q;
        gy$0$clock = clock;
        gy$0$d = gy$0$q;
        ddx_o$0$clock = clock;
        ddx_o$0$d = ddx_o$0$q;
        p$1$clock = clock;
        p$1$d = p$1$q;
        gx$1$clock = clock;
        gx$1$d = gx$1$q;
        gy$1$clock = clock;
        gy$1$d = gy$1$q;
        ddx_o$1$clock = clock;
        ddx_o$1$d = ddx_o$1$q;
        p$2$clock = clock;
        p$2$d = p$2$q;
        gx$2$clock = clock;
        gx$2$d = gx$2$q;
        gy$2$clock = clock;
        gy$2$d = gy$2$q;
        ddx_o$2$clock = clock;
        ddx_o$2$d = ddx_o$2$q;
        p$3$clock = clock;
        p$3$d = p$3$q;
        gx$3$clock = clock;
        gx$3$d = gx$3$q;
        gy$3$clock = clock;
        gy$3$d = gy$3$q;
        ddx_o$3$clock = clock;
        ddx_o$3$d = ddx_o$3$q;
        mul$0$clock = clock;
        mul$1$clock = clock;
        mul$2$clock = clock;
        mul$3$clock = clock;
        mul$4$clock = clock;
        mul$5$clock = clock;
        mul$6$clock = clock;
        plane$0$clock = clock;
        plane$0$d = plane$0$q;
        inc0$0$clock = clock;
        inc0$0$d = inc0$0$q;
        inc1$0$clock = clock;
        inc1$0$d = inc1$0$q;
        plane$1$clock = clock;
        plane$1$d = plane$1$q;
        inc0$1$clock = clock;
        inc0$1$d = inc0$1$q;
        inc1$1$clock = clock;
        inc1$1$d = inc1$1$q;
        plane$2$clock = clock;
        plane$2$d = plane$2$q;
        inc0$2$clock = clock;
        inc0$2$d = inc0$2$q;
        inc1$2$clock = clock;
        inc1$2$d = inc1$2$q;
        plane$3$clock = clock;
        plane$3$d = plane$3$q;
        inc0$3$clock = clock;
        inc0$3$d = inc0$3$q;
        inc1$3$clock = clock;
        inc1$3$d = inc1$3$q;
        plane$4$clock = clock;
        plane$4$d = plane$4$q;
        inc0$4$clock = clock;
        inc0$4$d = inc0$4$q;
        inc1$4$clock = clock;
        inc1$4$d = inc1$4$q;
        plane$5$clock = clock;
        plane$5$d = plane$5$q;
        inc0$5$clock = clock;
        inc0$5$d = inc0$5$q;
        inc1$5$clock = clock;
        inc1$5$d = inc1$5$q;
        plane$6$clock = clock;
        plane$6$d = plane$6$q;
        inc0$6$clock = clock;
        inc0$6$d = inc0$6$q;
        inc1$6$clock = clock;
        inc1$6$d = inc1$6$q;
        plane$7$clock = clock;
        plane$7$d = plane$7$q;
        inc0$7$clock = clock;
        inc0$7$d = inc0$7$q;
        inc1$7$clock = clock;
        inc1$7$d = inc1$7$q;
        plane$8$clock = clock;
        plane$8$d = plane$8$q;
        inc0$8$clock = clock;
        inc0$8$d = inc0$8$q;
        inc1$8$clock = clock;
        inc1$8$d = inc1$8$q;
        plane$9$clock = clock;
        plane$9$d = plane$9$q;
        inc0$9$clock = clock;
        inc0$9$d = inc0$9$q;
        inc1$9$clock = clock;
        inc1$9$d = inc1$9$q;
        plane$10$clock = clock;
        plane$10$d = plane$10$q;
        inc0$10$clock = clock;
        inc0$10$d = inc0$10$q;
        inc1$10$clock = clock;
        inc1$10$d = inc1$10$q;
        plane$11$clock = clock;
        plane$11$d = plane$11$q;
        inc0$11$clock = clock;
        inc0$11$d = inc0$11$q;
        inc1$11$clock = clock;
        inc1$11$d = inc1$11$q;
        maj_left$0 = area$q[area_msb];
        maj_left$1 = sign$1$q;
        maj_left$2 = sign$2$q;
        maj_left$3 = sign$3$q;
        maj_left$4 = sign$4$q;
        maj_left$5 = sign$5$q;
        valid = tok$5$q[last_bit];
        run = ~stall_r$q & ~(valid & out_hold & ~out$ready);
        out$valid = valid;
        inp$ready = run & ~gate_r$q;
        take = inp$valid & inp$ready;
        if (run) begin
            phase$d = phase$q + 32'h1;
            if (phase$q == ii_m1) begin
                phase$d = 32'h0;
            end
            if (take) begin
                phase$d = 32'h1;
            end
            if (enter$1) begin
                geo$1$d = geo$0$q;
                sign$1$d = maj_left$0;
                exp$1$d = exp$0$q;
                mant$1$d = mant$0$q;
                x$3$d = x$0$q;
                r$3$d = r$0$q;
                q$3$d = q$0$q;
                rho$3$d = rho$0$q;
                x$4$d = x$1$q;
                r$4$d = r$1$q;
                q$4$d = q$1$q;
                rho$4$d = rho$1$q;
                x$5$d = x$2$q;
                r$5$d = r$2$q;
                q$5$d = q$2$q;
                rho$5$d = rho$2$q;
            end
            if (enter$2) begin
                geo$2$d = geo$1$q;
                sign$2$d = maj_left$1;
                exp$2$d = exp$1$q;
                mant$2$d = mant$1$q;
                x$6$d = x$3$q;
                r$6$d = r$3$q;
                q$6$d = q$3$q;
                rho$6$d = rho$3$q;
                x$7$d = x$4$q;
                r$7$d = r$4$q;
                q$7$d = q$4$q;
                rho$7$d = rho$4$q;
                x$8$d = x$5$q;
                r$8$d = r$5$q;
                q$8$d = q$5$q;
                rho$8$d = rho$5$q;
            end
            if (enter$3) begin
                geo$3$d = geo$2$q;
                sign$3$d = maj_left$2;
                exp$3$d = exp$2$q;
                mant$3$d = mant$2$q;
                x$9$d = x$6$q;
                r$9$d = r$6$q;
                q$9$d = q$6$q;
                rho$9$d = rho$6$q;
                x$10$d = x$7$q;
                r$10$d = r$7$q;
                q$10$d = q$7$q;
                rho$10$d = rho$7$q;
                x$11$d = x$8$q;
                r$11$d = r$8$q;
                q$11$d = q$8$q;
                rho$11$d = rho$8$q;
            end
            if (enter$4) begin
                geo$4$d = geo$3$q;
                sign$4$d = maj_left$3;
                exp$4$d = exp$3$q;
                mant$4$d = mant$3$q;
                x$12$d = x$9$q;
                r$12$d = r$9$q;
                q$12$d = q$9$q;
                rho$12$d = rho$9$q;
                x$13$d = x$10$q;
                r$13$d = r$10$q;
                q$13$d = q$10$q;
                rho$13$d = rho$10$q;
                x$14$d = x$11$q;
                r$14$d = r$11$q;
                q$14$d = q$11$q;
                rho$14$d = rho$11$q;
            end
            if (enter$5) begin
                geo$5$d = geo$4$q;
                sign$5$d = maj_left$4;
                exp$5$d = exp$4$q;
                mant$5$d = mant$4$q;
                x$15$d = x$12$q;
                r$15$d = r$12$q;
                q$15$d = q$12$q;
                rho$15$d = rho$12$q;
                x$16$d = x$13$q;
                r$16$d = r$13$q;
                q$16$d = q$13$q;
                rho$16$d = rho$13$q;
                x$17$d = x$14$q;
                r$17$d = r$14$q;
                q$17$d = q$14$q;
                rho$17$d = rho$14$q;
            end
        end
        if (take) begin
            geo$0$d = geometry$word;
        end
        enter$0 = take;
        enter$1 = tok$0$q[end_bit$0];
        enter$2 = tok$1$q[end_bit$1];
        enter$3 = tok$2$q[end_bit$2];
        enter$4 = tok$3$q[end_bit$3];
        enter$5 = tok$4$q[end_bit$4];
        tok_n$0 = tok$0$q;
        if (run) begin
            tok_n$0 = (tok$0$q << 32'h1) & tok_mask$0;
            if (enter$0) begin
                tok_n$0 = ((tok$0$q << 32'h1) | 32'h1) & tok_mask$0;
            end
        end
        tok$0$d = tok_n$0;
        tok_n$1 = tok$1$q;
        if (run) begin
            tok_n$1 = (tok$1$q << 32'h1) & tok_mask$1;
            if (enter$1) begin
                tok_n$1 = ((tok$1$q << 32'h1) | 32'h1) & tok_mask$1;
            end
        end
        tok$1$d = tok_n$1;
        tok_n$2 = tok$2$q;
        if (run) begin
            tok_n$2 = (tok$2$q << 32'h1) & tok_mask$2;
            if (enter$2) begin
                tok_n$2 = ((tok$2$q << 32'h1) | 32'h1) & tok_mask$2;
            end
        end
        tok$2$d = tok_n$2;
        tok_n$3 = tok$3$q;
        if (run) begin
            tok_n$3 = (tok$3$q << 32'h1) & tok_mask$3;
            if (enter$3) begin
                tok_n$3 = ((tok$3$q << 32'h1) | 32'h1) & tok_mask$3;
            end
        end
        tok$3$d = tok_n$3;
        tok_n$4 = tok$4$q;
        if (run) begin
            tok_n$4 = (tok$4$q << 32'h1) & tok_mask$4;
            if (enter$4) begin
                tok_n$4 = ((tok$4$q << 32'h1) | 32'h1) & tok_mask$4;
            end
        end
        tok$4$d = tok_n$4;
        tok_n$5 = tok$5$q;
        if (run) begin
            tok_n$5 = (tok$5$q << 32'h1) & tok_mask$5;
            if (enter$5) begin
                tok_n$5 = ((tok$5$q << 32'h1) | 32'h1) & tok_mask$5;
            end
        end
        tok$5$d = tok_n$5;
        valid_n = tok_n$5[last_bit];
        stall_r$d = valid_n & ~out_free_next;
        act$0 = 1'b0;
        add$0 = 1'b0;
        if (view$0 == 0) begin
            act$0 = tok$0$q[act_bit$0];
        end
        if (view_add$0 == 0) begin
            add$0 = tok$0$q[add_bit$0];
        end
        if (view$0 == 1) begin
            act$0 = tok$1$q[act_bit$0];
        end
        if (view_add$0 == 1) begin
            add$0 = tok$1$q[add_bit$0];
        end
        if (view$0 == 2) begin
            act$0 = tok$2$q[act_bit$0];
        end
        if (view_add$0 == 2) begin
            add$0 = tok$2$q[add_bit$0];
        end
        if (view$0 == 3) begin
            act$0 = tok$3$q[act_bit$0];
        end
        if (view_add$0 == 3) begin
            add$0 = tok$3$q[add_bit$0];
        end
        if (view$0 == 4) begin
            act$0 = tok$4$q[act_bit$0];
        end
        if (view_add$0 == 4) begin
            add$0 = tok$4$q[add_bit$0];
        end
        if (view$0 == 5) begin
            act$0 = tok$5$q[act_bit$0];
        end
        if (view_add$0 == 5) begin
            add$0 = tok$5$q[add_bit$0];
        end
        act$1 = 1'b0;
        add$1 = 1'b0;
        if (view$1 == 0) begin
            act$1 = tok$0$q[act_bit$1];
        end
        if (view_add$1 == 0) begin
            add$1 = tok$0$q[add_bit$1];
        end
        if (view$1 == 1) begin
            act$1 = tok$1$q[act_bit$1];
        end
        if (view_add$1 == 1) begin
            add$1 = tok$1$q[add_bit$1];
        end
        if (view$1 == 2) begin
            act$1 = tok$2$q[act_bit$1];
        end
        if (view_add$1 == 2) begin
            add$1 = tok$2$q[add_bit$1];
        end
        if (view$1 == 3) begin
            act$1 = tok$3$q[act_bit$1];
        end
        if (view_add$1 == 3) begin
            add$1 = tok$3$q[add_bit$1];
        end
        if (view$1 == 4) begin
            act$1 = tok$4$q[act_bit$1];
        end
        if (view_add$1 == 4) begin
            add$1 = tok$4$q[add_bit$1];
        end
        if (view$1 == 5) begin
            act$1 = tok$5$q[act_bit$1];
        end
        if (view_add$1 == 5) begin
            add$1 = tok$5$q[add_bit$1];
        end
        act$2 = 1'b0;
        add$2 = 1'b0;
        if (view$2 == 0) begin
            act$2 = tok$0$q[act_bit$2];
        end
        if (view_add$2 == 0) begin
            add$2 = tok$0$q[add_bit$2];
        end
        if (view$2 == 1) begin
            act$2 = tok$1$q[act_bit$2];
        end
        if (view_add$2 == 1) begin
            add$2 = tok$1$q[add_bit$2];
        end
        if (view$2 == 2) begin
            act$2 = tok$2$q[act_bit$2];
        end
        if (view_add$2 == 2) begin
            add$2 = tok$2$q[add_bit$2];
        end
        if (view$2 == 3) begin
            act$2 = tok$3$q[act_bit$2];
        end
        if (view_add$2 == 3) begin
            add$2 = tok$3$q[add_bit$2];
        end
        if (view$2 == 4) begin
            act$2 = tok$4$q[act_bit$2];
        end
        if (view_add$2 == 4) begin
            add$2 = tok$4$q[add_bit$2];
        end
        if (view$2 == 5) begin
            act$2 = tok$5$q[act_bit$2];
        end
        if (view_add$2 == 5) begin
            add$2 = tok$5$q[add_bit$2];
        end
        act$3 = 1'b0;
        add$3 = 1'b0;
        if (view$3 == 0) begin
            act$3 = tok$0$q[act_bit$3];
        end
        if (view_add$3 == 0) begin
            add$3 = tok$0$q[add_bit$3];
        end
        if (view$3 == 1) begin
            act$3 = tok$1$q[act_bit$3];
        end
        if (view_add$3 == 1) begin
            add$3 = tok$1$q[add_bit$3];
        end
        if (view$3 == 2) begin
            act$3 = tok$2$q[act_bit$3];
        end
        if (view_add$3 == 2) begin
            add$3 = tok$2$q[add_bit$3];
        end
        if (view$3 == 3) begin
            act$3 = tok$3$q[act_bit$3];
        end
        if (view_add$3 == 3) begin
            add$3 = tok$3$q[add_bit$3];
        end
        if (view$3 == 4) begin
            act$3 = tok$4$q[act_bit$3];
        end
        if (view_add$3 == 4) begin
            add$3 = tok$4$q[add_bit$3];
        end
        if (view$3 == 5) begin
            act$3 = tok$5$q[act_bit$3];
        end
        if (view_add$3 == 5) begin
            add$3 = tok$5$q[add_bit$3];
        end
        act$4 = 1'b0;
        add$4 = 1'b0;
        if (view$4 == 0) begin
            act$4 = tok$0$q[act_bit$4];
        end
        if (view_add$4 == 0) begin
            add$4 = tok$0$q[add_bit$4];
        end
        if (view$4 == 1) begin
            act$4 = tok$1$q[act_bit$4];
        end
        if (view_add$4 == 1) begin
            add$4 = tok$1$q[add_bit$4];
        end
        if (view$4 == 2) begin
            act$4 = tok$2$q[act_bit$4];
        end
        if (view_add$4 == 2) begin
            add$4 = tok$2$q[add_bit$4];
        end
        if (view$4 == 3) begin
            act$4 = tok$3$q[act_bit$4];
        end
        if (view_add$4 == 3) begin
            add$4 = tok$3$q[add_bit$4];
        end
        if (view$4 == 4) begin
            act$4 = tok$4$q[act_bit$4];
        end
        if (view_add$4 == 4) begin
            add$4 = tok$4$q[add_bit$4];
        end
        if (view$4 == 5) begin
            act$4 = tok$5$q[act_bit$4];
        end
        if (view_add$4 == 5) begin
            add$4 = tok$5$q[add_bit$4];
        end
        act$5 = 1'b0;
        add$5 = 1'b0;
        if (view$5 == 0) begin
            act$5 = tok$0$q[act_bit$5];
        end
        if (view_add$5 == 0) begin
            add$5 = tok$0$q[add_bit$5];
        end
        if (view$5 == 1) begin
            act$5 = tok$1$q[act_bit$5];
        end
        if (view_add$5 == 1) begin
            add$5 = tok$1$q[add_bit$5];
        end
        if (view$5 == 2) begin
            act$5 = tok$2$q[act_bit$5];
        end
        if (view_add$5 == 2) begin
            add$5 = tok$2$q[add_bit$5];
        end
        if (view$5 == 3) begin
            act$5 = tok$3$q[act_bit$5];
        end
        if (view_add$5 == 3) begin
            add$5 = tok$3$q[add_bit$5];
        end
        if (view$5 == 4) begin
            act$5 = tok$4$q[act_bit$5];
        end
        if (view_add$5 == 4) begin
            add$5 = tok$4$q[add_bit$5];
        end
        if (view$5 == 5) begin
            act$5 = tok$5$q[act_bit$5];
        end
        if (view_add$5 == 5) begin
            add$5 = tok$5$q[add_bit$5];
        end
        act$6 = 1'b0;
        add$6 = 1'b0;
        if (view$6 == 0) begin
            act$6 = tok$0$q[act_bit$6];
        end
        if (view_add$6 == 0) begin
            add$6 = tok$0$q[add_bit$6];
        end
        if (view$6 == 1) begin
            act$6 = tok$1$q[act_bit$6];
        end
        if (view_add$6 == 1) begin
            add$6 = tok$1$q[add_bit$6];
        end
        if (view$6 == 2) begin
            act$6 = tok$2$q[act_bit$6];
        end
        if (view_add$6 == 2) begin
            add$6 = tok$2$q[add_bit$6];
        end
        if (view$6 == 3) begin
            act$6 = tok$3$q[act_bit$6];
        end
        if (view_add$6 == 3) begin
            add$6 = tok$3$q[add_bit$6];
        end
        if (view$6 == 4) begin
            act$6 = tok$4$q[act_bit$6];
        end
        if (view_add$6 == 4) begin
            add$6 = tok$4$q[add_bit$6];
        end
        if (view$6 == 5) begin
            act$6 = tok$5$q[act_bit$6];
        end
        if (view_add$6 == 5) begin
            add$6 = tok$5$q[add_bit$6];
        end
        act$7 = 1'b0;
        add$7 = 1'b0;
        if (view$7 == 0) begin
            act$7 = tok$0$q[act_bit$7];
        end
        if (view_add$7 == 0) begin
            add$7 = tok$0$q[add_bit$7];
        end
        if (view$7 == 1) begin
            act$7 = tok$1$q[act_bit$7];
        end
        if (view_add$7 == 1) begin
            add$7 = tok$1$q[add_bit$7];
        end
        if (view$7 == 2) begin
            act$7 = tok$2$q[act_bit$7];
        end
        if (view_add$7 == 2) begin
            add$7 = tok$2$q[add_bit$7];
        end
        if (view$7 == 3) begin
            act$7 = tok$3$q[act_bit$7];
        end
        if (view_add$7 == 3) begin
            add$7 = tok$3$q[add_bit$7];
        end
        if (view$7 == 4) begin
            act$7 = tok$4$q[act_bit$7];
        end
        if (view_add$7 == 4) begin
            add$7 = tok$4$q[add_bit$7];
        end
        if (view$7 == 5) begin
            act$7 = tok$5$q[act_bit$7];
        end
        if (view_add$7 == 5) begin
            add$7 = tok$5$q[add_bit$7];
        end
        act$8 = 1'b0;
        add$8 = 1'b0;
        if (view$8 == 0) begin
            act$8 = tok$0$q[act_bit$8];
        end
        if (view_add$8 == 0) begin
            add$8 = tok$0$q[add_bit$8];
        end
        if (view$8 == 1) begin
            act$8 = tok$1$q[act_bit$8];
        end
        if (view_add$8 == 1) begin
            add$8 = tok$1$q[add_bit$8];
        end
        if (view$8 == 2) begin
            act$8 = tok$2$q[act_bit$8];
        end
        if (view_add$8 == 2) begin
            add$8 = tok$2$q[add_bit$8];
        end
        if (view$8 == 3) begin
            act$8 = tok$3$q[act_bit$8];
        end
        if (view_add$8 == 3) begin
            add$8 = tok$3$q[add_bit$8];
        end
        if (view$8 == 4) begin
            act$8 = tok$4$q[act_bit$8];
        end
        if (view_add$8 == 4) begin
            add$8 = tok$4$q[add_bit$8];
        end
        if (view$8 == 5) begin
            act$8 = tok$5$q[act_bit$8];
        end
        if (view_add$8 == 5) begin
            add$8 = tok$5$q[add_bit$8];
        end
        act$9 = 1'b0;
        add$9 = 1'b0;
        if (view$9 == 0) begin
            act$9 = tok$0$q[act_bit$9];
        end
        if (view_add$9 == 0) begin
            add$9 = tok$0$q[add_bit$9];
        end
        if (view$9 == 1) begin
            act$9 = tok$1$q[act_bit$9];
        end
        if (view_add$9 == 1) begin
            add$9 = tok$1$q[add_bit$9];
        end
        if (view$9 == 2) begin
            act$9 = tok$2$q[act_bit$9];
        end
        if (view_add$9 == 2) begin
            add$9 = tok$2$q[add_bit$9];
        end
        if (view$9 == 3) begin
            act$9 = tok$3$q[act_bit$9];
        end
        if (view_add$9 == 3) begin
            add$9 = tok$3$q[add_bit$9];
        end
        if (view$9 == 4) begin
            act$9 = tok$4$q[act_bit$9];
        end
        if (view_add$9 == 4) begin
            add$9 = tok$4$q[add_bit$9];
        end
        if (view$9 == 5) begin
            act$9 = tok$5$q[act_bit$9];
        end
        if (view_add$9 == 5) begin
            add$9 = tok$5$q[add_bit$9];
        end
        act$10 = 1'b0;
        add$10 = 1'b0;
        if (view$10 == 0) begin
            act$10 = tok$0$q[act_bit$10];
        end
        if (view_add$10 == 0) begin
            add$10 = tok$0$q[add_bit$10];
        end
        if (view$10 == 1) begin
            act$10 = tok$1$q[act_bit$10];
        end
        if (view_add$10 == 1) begin
            add$10 = tok$1$q[add_bit$10];
        end
        if (view$10 == 2) begin
            act$10 = tok$2$q[act_bit$10];
        end
        if (view_add$10 == 2) begin
            add$10 = tok$2$q[add_bit$10];
        end
        if (view$10 == 3) begin
            act$10 = tok$3$q[act_bit$10];
        end
        if (view_add$10 == 3) begin
            add$10 = tok$3$q[add_bit$10];
        end
        if (view$10 == 4) begin
            act$10 = tok$4$q[act_bit$10];
        end
        if (view_add$10 == 4) begin
            add$10 = tok$4$q[add_bit$10];
        end
        if (view$10 == 5) begin
            act$10 = tok$5$q[act_bit$10];
        end
        if (view_add$10 == 5) begin
            add$10 = tok$5$q[add_bit$10];
        end
        act$11 = 1'b0;
        add$11 = 1'b0;
        if (view$11 == 0) begin
            act$11 = tok$0$q[act_bit$11];
        end
        if (view_add$11 == 0) begin
            add$11 = tok$0$q[add_bit$11];
        end
        if (view$11 == 1) begin
            act$11 = tok$1$q[act_bit$11];
        end
        if (view_add$11 == 1) begin
            add$11 = tok$1$q[add_bit$11];
        end
        if (view$11 == 2) begin
            act$11 = tok$2$q[act_bit$11];
        end
        if (view_add$11 == 2) begin
            add$11 = tok$2$q[add_bit$11];
        end
        if (view$11 == 3) begin
            act$11 = tok$3$q[act_bit$11];
        end
        if (view_add$11 == 3) begin
            add$11 = tok$3$q[add_bit$11];
        end
        if (view$11 == 4) begin
            act$11 = tok$4$q[act_bit$11];
        end
        if (view_add$11 == 4) begin
            add$11 = tok$4$q[add_bit$11];
        end
        if (view$11 == 5) begin
            act$11 = tok$5$q[act_bit$11];
        end
        if (view_add$11 == 5) begin
            add$11 = tok$5$q[add_bit$11];
        end
        act$12 = 1'b0;
        add$12 = 1'b0;
        if (view$12 == 0) begin
            act$12 = tok$0$q[act_bit$12];
        end
        if (view_add$12 == 0) begin
            add$12 = tok$0$q[add_bit$12];
        end
        if (view$12 == 1) begin
            act$12 = tok$1$q[act_bit$12];
        end
        if (view_add$12 == 1) begin
            add$12 = tok$1$q[add_bit$12];
        end
        if (view$12 == 2) begin
            act$12 = tok$2$q[act_bit$12];
        end
        if (view_add$12 == 2) begin
            add$12 = tok$2$q[add_bit$12];
        end
        if (view$12 == 3) begin
            act$12 = tok$3$q[act_bit$12];
        end
        if (view_add$12 == 3) begin
            add$12 = tok$3$q[add_bit$12];
        end
        if (view$12 == 4) begin
            act$12 = tok$4$q[act_bit$12];
        end
        if (view_add$12 == 4) begin
            add$12 = tok$4$q[add_bit$12];
        end
        if (view$12 == 5) begin
            act$12 = tok$5$q[act_bit$12];
        end
        if (view_add$12 == 5) begin
            add$12 = tok$5$q[add_bit$12];
        end
        act$13 = 1'b0;
        add$13 = 1'b0;
        if (view$13 == 0) begin
            act$13 = tok$0$q[act_bit$13];
        end
        if (view_add$13 == 0) begin
            add$13 = tok$0$q[add_bit$13];
        end
        if (view$13 == 1) begin
            act$13 = tok$1$q[act_bit$13];
        end
        if (view_add$13 == 1) begin
            add$13 = tok$1$q[add_bit$13];
        end
        if (view$13 == 2) begin
            act$13 = tok$2$q[act_bit$13];
        end
        if (view_add$13 == 2) begin
            add$13 = tok$2$q[add_bit$13];
        end
        if (view$13 == 3) begin
            act$13 = tok$3$q[act_bit$13];
        end
        if (view_add$13 == 3) begin
            add$13 = tok$3$q[add_bit$13];
        end
        if (view$13 == 4) begin
            act$13 = tok$4$q[act_bit$13];
        end
        if (view_add$13 == 4) begin
            add$13 = tok$4$q[add_bit$13];
        end
        if (view$13 == 5) begin
            act$13 = tok$5$q[act_bit$13];
        end
        if (view_add$13 == 5) begin
            add$13 = tok$5$q[add_bit$13];
        end
        act$14 = 1'b0;
        add$14 = 1'b0;
        if (view$14 == 0) begin
            act$14 = tok$0$q[act_bit$14];
        end
        if (view_add$14 == 0) begin
            add$14 = tok$0$q[add_bit$14];
        end
        if (view$14 == 1) begin
            act$14 = tok$1$q[act_bit$14];
        end
        if (view_add$14 == 1) begin
            add$14 = tok$1$q[add_bit$14];
        end
        if (view$14 == 2) begin
            act$14 = tok$2$q[act_bit$14];
        end
        if (view_add$14 == 2) begin
            add$14 = tok$2$q[add_bit$14];
        end
        if (view$14 == 3) begin
            act$14 = tok$3$q[act_bit$14];
        end
        if (view_add$14 == 3) begin
            add$14 = tok$3$q[add_bit$14];
        end
        if (view$14 == 4) begin
            act$14 = tok$4$q[act_bit$14];
        end
        if (view_add$14 == 4) begin
            add$14 = tok$4$q[add_bit$14];
        end
        if (view$14 == 5) begin
            act$14 = tok$5$q[act_bit$14];
        end
        if (view_add$14 == 5) begin
            add$14 = tok$5$q[add_bit$14];
        end
        act$15 = 1'b0;
        add$15 = 1'b0;
        if (view$15 == 0) begin
            act$15 = tok$0$q[act_bit$15];
        end
        if (view_add$15 == 0) begin
            add$15 = tok$0$q[add_bit$15];
        end
        if (view$15 == 1) begin
            act$15 = tok$1$q[act_bit$15];
        end
        if (view_add$15 == 1) begin
            add$15 = tok$1$q[add_bit$15];
        end
        if (view$15 == 2) begin
            act$15 = tok$2$q[act_bit$15];
        end
        if (view_add$15 == 2) begin
            add$15 = tok$2$q[add_bit$15];
        end
        if (view$15 == 3) begin
            act$15 = tok$3$q[act_bit$15];
        end
        if (view_add$15 == 3) begin
            add$15 = tok$3$q[add_bit$15];
        end
        if (view$15 == 4) begin
            act$15 = tok$4$q[act_bit$15];
        end
        if (view_add$15 == 4) begin
            add$15 = tok$4$q[add_bit$15];
        end
        if (view$15 == 5) begin
            act$15 = tok$5$q[act_bit$15];
        end
        if (view_add$15 == 5) begin
            add$15 = tok$5$q[add_bit$15];
        end
        act$16 = 1'b0;
        add$16 = 1'b0;
        if (view$16 == 0) begin
            act$16 = tok$0$q[act_bit$16];
        end
        if (view_add$16 == 0) begin
            add$16 = tok$0$q[add_bit$16];
        end
        if (view$16 == 1) begin
            act$16 = tok$1$q[act_bit$16];
        end
        if (view_add$16 == 1) begin
            add$16 = tok$1$q[add_bit$16];
        end
        if (view$16 == 2) begin
            act$16 = tok$2$q[act_bit$16];
        end
        if (view_add$16 == 2) begin
            add$16 = tok$2$q[add_bit$16];
        end
        if (view$16 == 3) begin
            act$16 = tok$3$q[act_bit$16];
        end
        if (view_add$16 == 3) begin
            add$16 = tok$3$q[add_bit$16];
        end
        if (view$16 == 4) begin
            act$16 = tok$4$q[act_bit$16];
        end
        if (view_add$16 == 4) begin
            add$16 = tok$4$q[add_bit$16];
        end
        if (view$16 == 5) begin
            act$16 = tok$5$q[act_bit$16];
        end
        if (view_add$16 == 5) begin
            add$16 = tok$5$q[add_bit$16];
        end
        act$17 = 1'b0;
        add$17 = 1'b0;
        if (view$17 == 0) begin
            act$17 = tok$0$q[act_bit$17];
        end
        if (view_add$17 == 0) begin
            add$17 = tok$0$q[add_bit$17];
        end
        if (view$17 == 1) begin
            act$17 = tok$1$q[act_bit$17];
        end
        if (view_add$17 == 1) begin
            add$17 = tok$1$q[add_bit$17];
        end
        if (view$17 == 2) begin
            act$17 = tok$2$q[act_bit$17];
        end
        if (view_add$17 == 2) begin
            add$17 = tok$2$q[add_bit$17];
        end
        if (view$17 == 3) begin
            act$17 = tok$3$q[act_bit$17];
        end
        if (view_add$17 == 3) begin
            add$17 = tok$3$q[add_bit$17];
        end
        if (view$17 == 4) begin
            act$17 = tok$4$q[act_bit$17];
        end
        if (view_add$17 == 4) begin
            add$17 = tok$4$q[add_bit$17];
        end
        if (view$17 == 5) begin
            act$17 = tok$5$q[act_bit$17];
        end
        if (view_add$17 == 5) begin
            add$17 = tok$5$q[add_bit$17];
        end
        act$18 = 1'b0;
        add$18 = 1'b0;
        if (view$18 == 0) begin
            act$18 = tok$0$q[act_bit$18];
        end
        if (view_add$18 == 0) begin
            add$18 = tok$0$q[add_bit$18];
        end
        if (view$18 == 1) begin
            act$18 = tok$1$q[act_bit$18];
        end
        if (view_add$18 == 1) begin
            add$18 = tok$1$q[add_bit$18];
        end
        if (view$18 == 2) begin
            act$18 = tok$2$q[act_bit$18];
        end
        if (view_add$18 == 2) begin
            add$18 = tok$2$q[add_bit$18];
        end
        if (view$18 == 3) begin
            act$18 = tok$3$q[act_bit$18];
        end
        if (view_add$18 == 3) begin
            add$18 = tok$3$q[add_bit$18];
        end
        if (view$18 == 4) begin
            act$18 = tok$4$q[act_bit$18];
        end
        if (view_add$18 == 4) begin
            add$18 = tok$4$q[add_bit$18];
        end
        if (view$18 == 5) begin
            act$18 = tok$5$q[act_bit$18];
        end
        if (view_add$18 == 5) begin
            add$18 = tok$5$q[add_bit$18];
        end
        act$19 = 1'b0;
        add$19 = 1'b0;
        if (view$19 == 0) begin
            act$19 = tok$0$q[act_bit$19];
        end
        if (view_add$19 == 0) begin
            add$19 = tok$0$q[add_bit$19];
        end
        if (view$19 == 1) begin
            act$19 = tok$1$q[act_bit$19];
        end
        if (view_add$19 == 1) begin
            add$19 = tok$1$q[add_bit$19];
        end
        if (view$19 == 2) begin
            act$19 = tok$2$q[act_bit$19];
        end
        if (view_add$19 == 2) begin
            add$19 = tok$2$q[add_bit$19];
        end
        if (view$19 == 3) begin
            act$19 = tok$3$q[act_bit$19];
        end
        if (view_add$19 == 3) begin
            add$19 = tok$3$q[add_bit$19];
        end
        if (view$19 == 4) begin
            act$19 = tok$4$q[act_bit$19];
        end
        if (view_add$19 == 4) begin
            add$19 = tok$4$q[add_bit$19];
        end
        if (view$19 == 5) begin
            act$19 = tok$5$q[act_bit$19];
        end
        if (view_add$19 == 5) begin
            add$19 = tok$5$q[add_bit$19];
        end
        act$20 = 1'b0;
        add$20 = 1'b0;
        if (view$20 == 0) begin
            act$20 = tok$0$q[act_bit$20];
        end
        if (view_add$20 == 0) begin
            add$20 = tok$0$q[add_bit$20];
        end
        if (view$20 == 1) begin
            act$20 = tok$1$q[act_bit$20];
        end
        if (view_add$20 == 1) begin
            add$20 = tok$1$q[add_bit$20];
        end
        if (view$20 == 2) begin
            act$20 = tok$2$q[act_bit$20];
        end
        if (view_add$20 == 2) begin
            add$20 = tok$2$q[add_bit$20];
        end
        if (view$20 == 3) begin
            act$20 = tok$3$q[act_bit$20];
        end
        if (view_add$20 == 3) begin
            add$20 = tok$3$q[add_bit$20];
        end
        if (view$20 == 4) begin
            act$20 = tok$4$q[act_bit$20];
        end
        if (view_add$20 == 4) begin
            add$20 = tok$4$q[add_bit$20];
        end
        if (view$20 == 5) begin
            act$20 = tok$5$q[act_bit$20];
        end
        if (view_add$20 == 5) begin
            add$20 = tok$5$q[add_bit$20];
        end
        act$21 = 1'b0;
        add$21 = 1'b0;
        if (view$21 == 0) begin
            act$21 = tok$0$q[act_bit$21];
        end
        if (view_add$21 == 0) begin
            add$21 = tok$0$q[add_bit$21];
        end
        if (view$21 == 1) begin
            act$21 = tok$1$q[act_bit$21];
        end
        if (view_add$21 == 1) begin
            add$21 = tok$1$q[add_bit$21];
        end
        if (view$21 == 2) begin
            act$21 = tok$2$q[act_bit$21];
        end
        if (view_add$21 == 2) begin
            add$21 = tok$2$q[add_bit$21];
        end
        if (view$21 == 3) begin
            act$21 = tok$3$q[act_bit$21];
        end
        if (view_add$21 == 3) begin
            add$21 = tok$3$q[add_bit$21];
        end
        if (view$21 == 4) begin
            act$21 = tok$4$q[act_bit$21];
        end
        if (view_add$21 == 4) begin
            add$21 = tok$4$q[add_bit$21];
        end
        if (view$21 == 5) begin
            act$21 = tok$5$q[act_bit$21];
        end
        if (view_add$21 == 5) begin
            add$21 = tok$5$q[add_bit$21];
        end
        act$22 = 1'b0;
        add$22 = 1'b0;
        if (view$22 == 0) begin
            act$22 = tok$0$q[act_bit$22];
        end
        if (view_add$22 == 0) begin
            add$22 = tok$0$q[add_bit$22];
        end
        if (view$22 == 1) begin
            act$22 = tok$1$q[act_bit$22];
        end
        if (view_add$22 == 1) begin
            add$22 = tok$1$q[add_bit$22];
        end
        if (view$22 == 2) begin
            act$22 = tok$2$q[act_bit$22];
        end
        if (view_add$22 == 2) begin
            add$22 = tok$2$q[add_bit$22];
        end
        if (view$22 == 3) begin
            act$22 = tok$3$q[act_bit$22];
        end
        if (view_add$22 == 3) begin
            add$22 = tok$3$q[add_bit$22];
        end
        if (view$22 == 4) begin
            act$22 = tok$4$q[act_bit$22];
        end
        if (view_add$22 == 4) begin
            add$22 = tok$4$q[add_bit$22];
        end
        if (view$22 == 5) begin
            act$22 = tok$5$q[act_bit$22];
        end
        if (view_add$22 == 5) begin
            add$22 = tok$5$q[add_bit$22];
        end
        act$23 = 1'b0;
        add$23 = 1'b0;
        if (view$23 == 0) begin
            act$23 = tok$0$q[act_bit$23];
        end
        if (view_add$23 == 0) begin
            add$23 = tok$0$q[add_bit$23];
        end
        if (view$23 == 1) begin
            act$23 = tok$1$q[act_bit$23];
        end
        if (view_add$23 == 1) begin
            add$23 = tok$1$q[add_bit$23];
        end
        if (view$23 == 2) begin
            act$23 = tok$2$q[act_bit$23];
        end
        if (view_add$23 == 2) begin
            add$23 = tok$2$q[add_bit$23];
        end
        if (view$23 == 3) begin
            act$23 = tok$3$q[act_bit$23];
        end
        if (view_add$23 == 3) begin
            add$23 = tok$3$q[add_bit$23];
        end
        if (view$23 == 4) begin
            act$23 = tok$4$q[act_bit$23];
        end
        if (view_add$23 == 4) begin
            add$23 = tok$4$q[add_bit$23];
        end
        if (view$23 == 5) begin
            act$23 = tok$5$q[act_bit$23];
        end
        if (view_add$23 == 5) begin
            add$23 = tok$5$q[add_bit$23];
        end
        act$24 = 1'b0;
        add$24 = 1'b0;
        if (view$24 == 0) begin
            act$24 = tok$0$q[act_bit$24];
        end
        if (view_add$24 == 0) begin
            add$24 = tok$0$q[add_bit$24];
        end
        if (view$24 == 1) begin
            act$24 = tok$1$q[act_bit$24];
        end
        if (view_add$24 == 1) begin
            add$24 = tok$1$q[add_bit$24];
        end
        if (view$24 == 2) begin
            act$24 = tok$2$q[act_bit$24];
        end
        if (view_add$24 == 2) begin
            add$24 = tok$2$q[add_bit$24];
        end
        if (view$24 == 3) begin
            act$24 = tok$3$q[act_bit$24];
        end
        if (view_add$24 == 3) begin
            add$24 = tok$3$q[add_bit$24];
        end
        if (view$24 == 4) begin
            act$24 = tok$4$q[act_bit$24];
        end
        if (view_add$24 == 4) begin
            add$24 = tok$4$q[add_bit$24];
        end
        if (view$24 == 5) begin
            act$24 = tok$5$q[act_bit$24];
        end
        if (view_add$24 == 5) begin
            add$24 = tok$5$q[add_bit$24];
        end
        act$25 = 1'b0;
        add$25 = 1'b0;
        if (view$25 == 0) begin
            act$25 = tok$0$q[act_bit$25];
        end
        if (view_add$25 == 0) begin
            add$25 = tok$0$q[add_bit$25];
        end
        if (view$25 == 1) begin
            act$25 = tok$1$q[act_bit$25];
        end
        if (view_add$25 == 1) begin
            add$25 = tok$1$q[add_bit$25];
        end
        if (view$25 == 2) begin
            act$25 = tok$2$q[act_bit$25];
        end
        if (view_add$25 == 2) begin
            add$25 = tok$2$q[add_bit$25];
        end
        if (view$25 == 3) begin
            act$25 = tok$3$q[act_bit$25];
        end
        if (view_add$25 == 3) begin
            add$25 = tok$3$q[add_bit$25];
        end
        if (view$25 == 4) begin
            act$25 = tok$4$q[act_bit$25];
        end
        if (view_add$25 == 4) begin
            add$25 = tok$4$q[add_bit$25];
        end
        if (view$25 == 5) begin
            act$25 = tok$5$q[act_bit$25];
        end
        if (view_add$25 == 5) begin
            add$25 = tok$5$q[add_bit$25];
        end
        act$26 = 1'b0;
        add$26 = 1'b0;
        if (view$26 == 0) begin
            act$26 = tok$0$q[act_bit$26];
        end
        if (view_add$26 == 0) begin
            add$26 = tok$0$q[add_bit$26];
        end
        if (view$26 == 1) begin
            act$26 = tok$1$q[act_bit$26];
        end
        if (view_add$26 == 1) begin
            add$26 = tok$1$q[add_bit$26];
        end
        if (view$26 == 2) begin
            act$26 = tok$2$q[act_bit$26];
        end
        if (view_add$26 == 2) begin
            add$26 = tok$2$q[add_bit$26];
        end
        if (view$26 == 3) begin
            act$26 = tok$3$q[act_bit$26];
        end
        if (view_add$26 == 3) begin
            add$26 = tok$3$q[add_bit$26];
        end
        if (view$26 == 4) begin
            act$26 = tok$4$q[act_bit$26];
        end
        if (view_add$26 == 4) begin
            add$26 = tok$4$q[add_bit$26];
        end
        if (view$26 == 5) begin
            act$26 = tok$5$q[act_bit$26];
        end
        if (view_add$26 == 5) begin
            add$26 = tok$5$q[add_bit$26];
        end
        act$27 = 1'b0;
        add$27 = 1'b0;
        if (view$27 == 0) begin
            act$27 = tok$0$q[act_bit$27];
        end
        if (view_add$27 == 0) begin
            add$27 = tok$0$q[add_bit$27];
        end
        if (view$27 == 1) begin
            act$27 = tok$1$q[act_bit$27];
        end
        if (view_add$27 == 1) begin
            add$27 = tok$1$q[add_bit$27];
        end
        if (view$27 == 2) begin
            act$27 = tok$2$q[act_bit$27];
        end
        if (view_add$27 == 2) begin
            add$27 = tok$2$q[add_bit$27];
        end
        if (view$27 == 3) begin
            act$27 = tok$3$q[act_bit$27];
        end
        if (view_add$27 == 3) begin
            add$27 = tok$3$q[add_bit$27];
        end
        if (view$27 == 4) begin
            act$27 = tok$4$q[act_bit$27];
        end
        if (view_add$27 == 4) begin
            add$27 = tok$4$q[add_bit$27];
        end
        if (view$27 == 5) begin
            act$27 = tok$5$q[act_bit$27];
        end
        if (view_add$27 == 5) begin
            add$27 = tok$5$q[add_bit$27];
        end
        act$28 = 1'b0;
        add$28 = 1'b0;
        if (view$28 == 0) begin
            act$28 = tok$0$q[act_bit$28];
        end
        if (view_add$28 == 0) begin
            add$28 = tok$0$q[add_bit$28];
        end
        if (view$28 == 1) begin
            act$28 = tok$1$q[act_bit$28];
        end
        if (view_add$28 == 1) begin
            add$28 = tok$1$q[add_bit$28];
        end
        if (view$28 == 2) begin
            act$28 = tok$2$q[act_bit$28];
        end
        if (view_add$28 == 2) begin
            add$28 = tok$2$q[add_bit$28];
        end
        if (view$28 == 3) begin
            act$28 = tok$3$q[act_bit$28];
        end
        if (view_add$28 == 3) begin
            add$28 = tok$3$q[add_bit$28];
        end
        if (view$28 == 4) begin
            act$28 = tok$4$q[act_bit$28];
        end
        if (view_add$28 == 4) begin
            add$28 = tok$4$q[add_bit$28];
        end
        if (view$28 == 5) begin
            act$28 = tok$5$q[act_bit$28];
        end
        if (view_add$28 == 5) begin
            add$28 = tok$5$q[add_bit$28];
        end
        act$29 = 1'b0;
        add$29 = 1'b0;
        if (view$29 == 0) begin
            act$29 = tok$0$q[act_bit$29];
        end
        if (view_add$29 == 0) begin
            add$29 = tok$0$q[add_bit$29];
        end
        if (view$29 == 1) begin
            act$29 = tok$1$q[act_bit$29];
        end
        if (view_add$29 == 1) begin
            add$29 = tok$1$q[add_bit$29];
        end
        if (view$29 == 2) begin
            act$29 = tok$2$q[act_bit$29];
        end
        if (view_add$29 == 2) begin
            add$29 = tok$2$q[add_bit$29];
        end
        if (view$29 == 3) begin
            act$29 = tok$3$q[act_bit$29];
        end
        if (view_add$29 == 3) begin
            add$29 = tok$3$q[add_bit$29];
        end
        if (view$29 == 4) begin
            act$29 = tok$4$q[act_bit$29];
        end
        if (view_add$29 == 4) begin
            add$29 = tok$4$q[add_bit$29];
        end
        if (view$29 == 5) begin
            act$29 = tok$5$q[act_bit$29];
        end
        if (view_add$29 == 5) begin
            add$29 = tok$5$q[add_bit$29];
        end
        act$30 = 1'b0;
        add$30 = 1'b0;
        if (view$30 == 0) begin
            act$30 = tok$0$q[act_bit$30];
        end
        if (view_add$30 == 0) begin
            add$30 = tok$0$q[add_bit$30];
        end
        if (view$30 == 1) begin
            act$30 = tok$1$q[act_bit$30];
        end
        if (view_add$30 == 1) begin
            add$30 = tok$1$q[add_bit$30];
        end
        if (view$30 == 2) begin
            act$30 = tok$2$q[act_bit$30];
        end
        if (view_add$30 == 2) begin
            add$30 = tok$2$q[add_bit$30];
        end
        if (view$30 == 3) begin
            act$30 = tok$3$q[act_bit$30];
        end
        if (view_add$30 == 3) begin
            add$30 = tok$3$q[add_bit$30];
        end
        if (view$30 == 4) begin
            act$30 = tok$4$q[act_bit$30];
        end
        if (view_add$30 == 4) begin
            add$30 = tok$4$q[add_bit$30];
        end
        if (view$30 == 5) begin
            act$30 = tok$5$q[act_bit$30];
        end
        if (view_add$30 == 5) begin
            add$30 = tok$5$q[add_bit$30];
        end
        act$31 = 1'b0;
        add$31 = 1'b0;
        if (view$31 == 0) begin
            act$31 = tok$0$q[act_bit$31];
        end
        if (view_add$31 == 0) begin
            add$31 = tok$0$q[add_bit$31];
        end
        if (view$31 == 1) begin
            act$31 = tok$1$q[act_bit$31];
        end
        if (view_add$31 == 1) begin
            add$31 = tok$1$q[add_bit$31];
        end
        if (view$31 == 2) begin
            act$31 = tok$2$q[act_bit$31];
        end
        if (view_add$31 == 2) begin
            add$31 = tok$2$q[add_bit$31];
        end
        if (view$31 == 3) begin
            act$31 = tok$3$q[act_bit$31];
        end
        if (view_add$31 == 3) begin
            add$31 = tok$3$q[add_bit$31];
        end
        if (view$31 == 4) begin
            act$31 = tok$4$q[act_bit$31];
        end
        if (view_add$31 == 4) begin
            add$31 = tok$4$q[add_bit$31];
        end
        if (view$31 == 5) begin
            act$31 = tok$5$q[act_bit$31];
        end
        if (view_add$31 == 5) begin
            add$31 = tok$5$q[add_bit$31];
        end
        act$32 = 1'b0;
        add$32 = 1'b0;
        if (view$32 == 0) begin
            act$32 = tok$0$q[act_bit$32];
        end
        if (view_add$32 == 0) begin
            add$32 = tok$0$q[add_bit$32];
        end
        if (view$32 == 1) begin
            act$32 = tok$1$q[act_bit$32];
        end
        if (view_add$32 == 1) begin
            add$32 = tok$1$q[add_bit$32];
        end
        if (view$32 == 2) begin
            act$32 = tok$2$q[act_bit$32];
        end
        if (view_add$32 == 2) begin
            add$32 = tok$2$q[add_bit$32];
        end
        if (view$32 == 3) begin
            act$32 = tok$3$q[act_bit$32];
        end
        if (view_add$32 == 3) begin
            add$32 = tok$3$q[add_bit$32];
        end
        if (view$32 == 4) begin
            act$32 = tok$4$q[act_bit$32];
        end
        if (view_add$32 == 4) begin
            add$32 = tok$4$q[add_bit$32];
        end
        if (view$32 == 5) begin
            act$32 = tok$5$q[act_bit$32];
        end
        if (view_add$32 == 5) begin
            add$32 = tok$5$q[add_bit$32];
        end
        act$33 = 1'b0;
        add$33 = 1'b0;
        if (view$33 == 0) begin
            act$33 = tok$0$q[act_bit$33];
        end
        if (view_add$33 == 0) begin
            add$33 = tok$0$q[add_bit$33];
        end
        if (view$33 == 1) begin
            act$33 = tok$1$q[act_bit$33];
        end
        if (view_add$33 == 1) begin
            add$33 = tok$1$q[add_bit$33];
        end
        if (view$33 == 2) begin
            act$33 = tok$2$q[act_bit$33];
        end
        if (view_add$33 == 2) begin
            add$33 = tok$2$q[add_bit$33];
        end
        if (view$33 == 3) begin
            act$33 = tok$3$q[act_bit$33];
        end
        if (view_add$33 == 3) begin
            add$33 = tok$3$q[add_bit$33];
        end
        if (view$33 == 4) begin
            act$33 = tok$4$q[act_bit$33];
        end
        if (view_add$33 == 4) begin
            add$33 = tok$4$q[add_bit$33];
        end
        if (view$33 == 5) begin
            act$33 = tok$5$q[act_bit$33];
        end
        if (view_add$33 == 5) begin
            add$33 = tok$5$q[add_bit$33];
        end
        act$34 = 1'b0;
        add$34 = 1'b0;
        if (view$34 == 0) begin
            act$34 = tok$0$q[act_bit$34];
        end
        if (view_add$34 == 0) begin
            add$34 = tok$0$q[add_bit$34];
        end
        if (view$34 == 1) begin
            act$34 = tok$1$q[act_bit$34];
        end
        if (view_add$34 == 1) begin
            add$34 = tok$1$q[add_bit$34];
        end
        if (view$34 == 2) begin
            act$34 = tok$2$q[act_bit$34];
        end
        if (view_add$34 == 2) begin
            add$34 = tok$2$q[add_bit$34];
        end
        if (view$34 == 3) begin
            act$34 = tok$3$q[act_bit$34];
        end
        if (view_add$34 == 3) begin
            add$34 = tok$3$q[add_bit$34];
        end
        if (view$34 == 4) begin
            act$34 = tok$4$q[act_bit$34];
        end
        if (view_add$34 == 4) begin
            add$34 = tok$4$q[add_bit$34];
        end
        if (view$34 == 5) begin
            act$34 = tok$5$q[act_bit$34];
        end
        if (view_add$34 == 5) begin
            add$34 = tok$5$q[add_bit$34];
        end
        act$35 = 1'b0;
        add$35 = 1'b0;
        if (view$35 == 0) begin
            act$35 = tok$0$q[act_bit$35];
        end
        if (view_add$35 == 0) begin
            add$35 = tok$0$q[add_bit$35];
        end
        if (view$35 == 1) begin
            act$35 = tok$1$q[act_bit$35];
        end
        if (view_add$35 == 1) begin
            add$35 = tok$1$q[add_bit$35];
        end
        if (view$35 == 2) begin
            act$35 = tok$2$q[act_bit$35];
        end
        if (view_add$35 == 2) begin
            add$35 = tok$2$q[add_bit$35];
        end
        if (view$35 == 3) begin
            act$35 = tok$3$q[act_bit$35];
        end
        if (view_add$35 == 3) begin
            add$35 = tok$3$q[add_bit$35];
        end
        if (view$35 == 4) begin
            act$35 = tok$4$q[act_bit$35];
        end
        if (view_add$35 == 4) begin
            add$35 = tok$4$q[add_bit$35];
        end
        if (view$35 == 5) begin
            act$35 = tok$5$q[act_bit$35];
        end
        if (view_add$35 == 5) begin
            add$35 = tok$5$q[add_bit$35];
        end
        act$36 = 1'b0;
        add$36 = 1'b0;
        if (view$36 == 0) begin
            act$36 = tok$0$q[act_bit$36];
        end
        if (view_add$36 == 0) begin
            add$36 = tok$0$q[add_bit$36];
        end
        if (view$36 == 1) begin
            act$36 = tok$1$q[act_bit$36];
        end
        if (view_add$36 == 1) begin
            add$36 = tok$1$q[add_bit$36];
        end
        if (view$36 == 2) begin
            act$36 = tok$2$q[act_bit$36];
        end
        if (view_add$36 == 2) begin
            add$36 = tok$2$q[add_bit$36];
        end
        if (view$36 == 3) begin
            act$36 = tok$3$q[act_bit$36];
        end
        if (view_add$36 == 3) begin
            add$36 = tok$3$q[add_bit$36];
        end
        if (view$36 == 4) begin
            act$36 = tok$4$q[act_bit$36];
        end
        if (view_add$36 == 4) begin
            add$36 = tok$4$q[add_bit$36];
        end
        if (view$36 == 5) begin
            act$36 = tok$5$q[act_bit$36];
        end
        if (view_add$36 == 5) begin
            add$36 = tok$5$q[add_bit$36];
        end
        act$37 = 1'b0;
        add$37 = 1'b0;
        if (view$37 == 0) begin
            act$37 = tok$0$q[act_bit$37];
        end
        if (view_add$37 == 0) begin
            add$37 = tok$0$q[add_bit$37];
        end
        if (view$37 == 1) begin
            act$37 = tok$1$q[act_bit$37];
        end
        if (view_add$37 == 1) begin
            add$37 = tok$1$q[add_bit$37];
        end
        if (view$37 == 2) begin
            act$37 = tok$2$q[act_bit$37];
        end
        if (view_add$37 == 2) begin
            add$37 = tok$2$q[add_bit$37];
        end
        if (view$37 == 3) begin
            act$37 = tok$3$q[act_bit$37];
        end
        if (view_add$37 == 3) begin
            add$37 = tok$3$q[add_bit$37];
        end
        if (view$37 == 4) begin
            act$37 = tok$4$q[act_bit$37];
        end
        if (view_add$37 == 4) begin
            add$37 = tok$4$q[add_bit$37];
        end
        if (view$37 == 5) begin
            act$37 = tok$5$q[act_bit$37];
        end
        if (view_add$37 == 5) begin
            add$37 = tok$5$q[add_bit$37];
        end
        act$38 = 1'b0;
        add$38 = 1'b0;
        if (view$38 == 0) begin
            act$38 = tok$0$q[act_bit$38];
        end
        if (view_add$38 == 0) begin
            add$38 = tok$0$q[add_bit$38];
        end
        if (view$38 == 1) begin
            act$38 = tok$1$q[act_bit$38];
        end
        if (view_add$38 == 1) begin
            add$38 = tok$1$q[add_bit$38];
        end
        if (view$38 == 2) begin
            act$38 = tok$2$q[act_bit$38];
        end
        if (view_add$38 == 2) begin
            add$38 = tok$2$q[add_bit$38];
        end
        if (view$38 == 3) begin
            act$38 = tok$3$q[act_bit$38];
        end
        if (view_add$38 == 3) begin
            add$38 = tok$3$q[add_bit$38];
        end
        if (view$38 == 4) begin
            act$38 = tok$4$q[act_bit$38];
        end
        if (view_add$38 == 4) begin
            add$38 = tok$4$q[add_bit$38];
        end
        if (view$38 == 5) begin
            act$38 = tok$5$q[act_bit$38];
        end
        if (view_add$38 == 5) begin
            add$38 = tok$5$q[add_bit$38];
        end
        act$39 = 1'b0;
        add$39 = 1'b0;
        if (view$39 == 0) begin
            act$39 = tok$0$q[act_bit$39];
        end
        if (view_add$39 == 0) begin
            add$39 = tok$0$q[add_bit$39];
        end
        if (view$39 == 1) begin
            act$39 = tok$1$q[act_bit$39];
        end
        if (view_add$39 == 1) begin
            add$39 = tok$1$q[add_bit$39];
        end
        if (view$39 == 2) begin
            act$39 = tok$2$q[act_bit$39];
        end
        if (view_add$39 == 2) begin
            add$39 = tok$2$q[add_bit$39];
        end
        if (view$39 == 3) begin
            act$39 = tok$3$q[act_bit$39];
        end
        if (view_add$39 == 3) begin
            add$39 = tok$3$q[add_bit$39];
        end
        if (view$39 == 4) begin
            act$39 = tok$4$q[act_bit$39];
        end
        if (view_add$39 == 4) begin
            add$39 = tok$4$q[add_bit$39];
        end
        if (view$39 == 5) begin
            act$39 = tok$5$q[act_bit$39];
        end
        if (view_add$39 == 5) begin
            add$39 = tok$5$q[add_bit$39];
        end
        act$40 = 1'b0;
        add$40 = 1'b0;
        if (view$40 == 0) begin
            act$40 = tok$0$q[act_bit$40];
        end
        if (view_add$40 == 0) begin
            add$40 = tok$0$q[add_bit$40];
        end
        if (view$40 == 1) begin
            act$40 = tok$1$q[act_bit$40];
        end
        if (view_add$40 == 1) begin
            add$40 = tok$1$q[add_bit$40];
        end
        if (view$40 == 2) begin
            act$40 = tok$2$q[act_bit$40];
        end
        if (view_add$40 == 2) begin
            add$40 = tok$2$q[add_bit$40];
        end
        if (view$40 == 3) begin
            act$40 = tok$3$q[act_bit$40];
        end
        if (view_add$40 == 3) begin
            add$40 = tok$3$q[add_bit$40];
        end
        if (view$40 == 4) begin
            act$40 = tok$4$q[act_bit$40];
        end
        if (view_add$40 == 4) begin
            add$40 = tok$4$q[add_bit$40];
        end
        if (view$40 == 5) begin
            act$40 = tok$5$q[act_bit$40];
        end
        if (view_add$40 == 5) begin
            add$40 = tok$5$q[add_bit$40];
        end
        act$41 = 1'b0;
        add$41 = 1'b0;
        if (view$41 == 0) begin
            act$41 = tok$0$q[act_bit$41];
        end
        if (view_add$41 == 0) begin
            add$41 = tok$0$q[add_bit$41];
        end
        if (view$41 == 1) begin
            act$41 = tok$1$q[act_bit$41];
        end
        if (view_add$41 == 1) begin
            add$41 = tok$1$q[add_bit$41];
        end
        if (view$41 == 2) begin
            act$41 = tok$2$q[act_bit$41];
        end
        if (view_add$41 == 2) begin
            add$41 = tok$2$q[add_bit$41];
        end
        if (view$41 == 3) begin
            act$41 = tok$3$q[act_bit$41];
        end
        if (view_add$41 == 3) begin
            add$41 = tok$3$q[add_bit$41];
        end
        if (view$41 == 4) begin
            act$41 = tok$4$q[act_bit$41];
        end
        if (view_add$41 == 4) begin
            add$41 = tok$4$q[add_bit$41];
        end
        if (view$41 == 5) begin
            act$41 = tok$5$q[act_bit$41];
        end
        if (view_add$41 == 5) begin
            add$41 = tok$5$q[add_bit$41];
        end
        act$42 = 1'b0;
        add$42 = 1'b0;
        if (view$42 == 0) begin
            act$42 = tok$0$q[act_bit$42];
        end
        if (view_add$42 == 0) begin
            add$42 = tok$0$q[add_bit$42];
        end
        if (view$42 == 1) begin
            act$42 = tok$1$q[act_bit$42];
        end
        if (view_add$42 == 1) begin
            add$42 = tok$1$q[add_bit$42];
        end
        if (view$42 == 2) begin
            act$42 = tok$2$q[act_bit$42];
        end
        if (view_add$42 == 2) begin
            add$42 = tok$2$q[add_bit$42];
        end
        if (view$42 == 3) begin
            act$42 = tok$3$q[act_bit$42];
        end
        if (view_add$42 == 3) begin
            add$42 = tok$3$q[add_bit$42];
        end
        if (view$42 == 4) begin
            act$42 = tok$4$q[act_bit$42];
        end
        if (view_add$42 == 4) begin
            add$42 = tok$4$q[add_bit$42];
        end
        if (view$42 == 5) begin
            act$42 = tok$5$q[act_bit$42];
        end
        if (view_add$42 == 5) begin
            add$42 = tok$5$q[add_bit$42];
        end
        act$43 = 1'b0;
        add$43 = 1'b0;
        if (view$43 == 0) begin
            act$43 = tok$0$q[act_bit$43];
        end
        if (view_add$43 == 0) begin
            add$43 = tok$0$q[add_bit$43];
        end
        if (view$43 == 1) begin
            act$43 = tok$1$q[act_bit$43];
        end
        if (view_add$43 == 1) begin
            add$43 = tok$1$q[add_bit$43];
        end
        if (view$43 == 2) begin
            act$43 = tok$2$q[act_bit$43];
        end
        if (view_add$43 == 2) begin
            add$43 = tok$2$q[add_bit$43];
        end
        if (view$43 == 3) begin
            act$43 = tok$3$q[act_bit$43];
        end
        if (view_add$43 == 3) begin
            add$43 = tok$3$q[add_bit$43];
        end
        if (view$43 == 4) begin
            act$43 = tok$4$q[act_bit$43];
        end
        if (view_add$43 == 4) begin
            add$43 = tok$4$q[add_bit$43];
        end
        if (view$43 == 5) begin
            act$43 = tok$5$q[act_bit$43];
        end
        if (view_add$43 == 5) begin
            add$43 = tok$5$q[add_bit$43];
        end
        act$44 = 1'b0;
        add$44 = 1'b0;
        if (view$44 == 0) begin
            act$44 = tok$0$q[act_bit$44];
        end
        if (view_add$44 == 0) begin
            add$44 = tok$0$q[add_bit$44];
        end
        if (view$44 == 1) begin
            act$44 = tok$1$q[act_bit$44];
        end
        if (view_add$44 == 1) begin
            add$44 = tok$1$q[add_bit$44];
        end
        if (view$44 == 2) begin
            act$44 = tok$2$q[act_bit$44];
        end
        if (view_add$44 == 2) begin
            add$44 = tok$2$q[add_bit$44];
        end
        if (view$44 == 3) begin
            act$44 = tok$3$q[act_bit$44];
        end
        if (view_add$44 == 3) begin
            add$44 = tok$3$q[add_bit$44];
        end
        if (view$44 == 4) begin
            act$44 = tok$4$q[act_bit$44];
        end
        if (view_add$44 == 4) begin
            add$44 = tok$4$q[add_bit$44];
        end
        if (view$44 == 5) begin
            act$44 = tok$5$q[act_bit$44];
        end
        if (view_add$44 == 5) begin
            add$44 = tok$5$q[add_bit$44];
        end
        act$45 = 1'b0;
        add$45 = 1'b0;
        if (view$45 == 0) begin
            act$45 = tok$0$q[act_bit$45];
        end
        if (view_add$45 == 0) begin
            add$45 = tok$0$q[add_bit$45];
        end
        if (view$45 == 1) begin
            act$45 = tok$1$q[act_bit$45];
        end
        if (view_add$45 == 1) begin
            add$45 = tok$1$q[add_bit$45];
        end
        if (view$45 == 2) begin
            act$45 = tok$2$q[act_bit$45];
        end
        if (view_add$45 == 2) begin
            add$45 = tok$2$q[add_bit$45];
        end
        if (view$45 == 3) begin
            act$45 = tok$3$q[act_bit$45];
        end
        if (view_add$45 == 3) begin
            add$45 = tok$3$q[add_bit$45];
        end
        if (view$45 == 4) begin
            act$45 = tok$4$q[act_bit$45];
        end
        if (view_add$45 == 4) begin
            add$45 = tok$4$q[add_bit$45];
        end
        if (view$45 == 5) begin
            act$45 = tok$5$q[act_bit$45];
        end
        if (view_add$45 == 5) begin
            add$45 = tok$5$q[add_bit$45];
        end
        act$46 = 1'b0;
        add$46 = 1'b0;
        if (view$46 == 0) begin
            act$46 = tok$0$q[act_bit$46];
        end
        if (view_add$46 == 0) begin
            add$46 = tok$0$q[add_bit$46];
        end
        if (view$46 == 1) begin
            act$46 = tok$1$q[act_bit$46];
        end
        if (view_add$46 == 1) begin
            add$46 = tok$1$q[add_bit$46];
        end
        if (view$46 == 2) begin
            act$46 = tok$2$q[act_bit$46];
        end
        if (view_add$46 == 2) begin
            add$46 = tok$2$q[add_bit$46];
        end
        if (view$46 == 3) begin
            act$46 = tok$3$q[act_bit$46];
        end
        if (view_add$46 == 3) begin
            add$46 = tok$3$q[add_bit$46];
        end
        if (view$46 == 4) begin
            act$46 = tok$4$q[act_bit$46];
        end
        if (view_add$46 == 4) begin
            add$46 = tok$4$q[add_bit$46];
        end
        if (view$46 == 5) begin
            act$46 = tok$5$q[act_bit$46];
        end
        if (view_add$46 == 5) begin
            add$46 = tok$5$q[add_bit$46];
        end
        act$47 = 1'b0;
        add$47 = 1'b0;
        if (view$47 == 0) begin
            act$47 = tok$0$q[act_bit$47];
        end
        if (view_add$47 == 0) begin
            add$47 = tok$0$q[add_bit$47];
        end
        if (view$47 == 1) begin
            act$47 = tok$1$q[act_bit$47];
        end
        if (view_add$47 == 1) begin
            add$47 = tok$1$q[add_bit$47];
        end
        if (view$47 == 2) begin
            act$47 = tok$2$q[act_bit$47];
        end
        if (view_add$47 == 2) begin
            add$47 = tok$2$q[add_bit$47];
        end
        if (view$47 == 3) begin
            act$47 = tok$3$q[act_bit$47];
        end
        if (view_add$47 == 3) begin
            add$47 = tok$3$q[add_bit$47];
        end
        if (view$47 == 4) begin
            act$47 = tok$4$q[act_bit$47];
        end
        if (view_add$47 == 4) begin
            add$47 = tok$4$q[add_bit$47];
        end
        if (view$47 == 5) begin
            act$47 = tok$5$q[act_bit$47];
        end
        if (view_add$47 == 5) begin
            add$47 = tok$5$q[add_bit$47];
        end
        act$48 = 1'b0;
        add$48 = 1'b0;
        if (view$48 == 0) begin
            act$48 = tok$0$q[act_bit$48];
        end
        if (view_add$48 == 0) begin
            add$48 = tok$0$q[add_bit$48];
        end
        if (view$48 == 1) begin
            act$48 = tok$1$q[act_bit$48];
        end
        if (view_add$48 == 1) begin
            add$48 = tok$1$q[add_bit$48];
        end
        if (view$48 == 2) begin
            act$48 = tok$2$q[act_bit$48];
        end
        if (view_add$48 == 2) begin
            add$48 = tok$2$q[add_bit$48];
        end
        if (view$48 == 3) begin
            act$48 = tok$3$q[act_bit$48];
        end
        if (view_add$48 == 3) begin
            add$48 = tok$3$q[add_bit$48];
        end
        if (view$48 == 4) begin
            act$48 = tok$4$q[act_bit$48];
        end
        if (view_add$48 == 4) begin
            add$48 = tok$4$q[add_bit$48];
        end
        if (view$48 == 5) begin
            act$48 = tok$5$q[act_bit$48];
        end
        if (view_add$48 == 5) begin
            add$48 = tok$5$q[add_bit$48];
        end
        act$49 = 1'b0;
        add$49 = 1'b0;
        if (view$49 == 0) begin
            act$49 = tok$0$q[act_bit$49];
        end
        if (view_add$49 == 0) begin
            add$49 = tok$0$q[add_bit$49];
        end
        if (view$49 == 1) begin
            act$49 = tok$1$q[act_bit$49];
        end
        if (view_add$49 == 1) begin
            add$49 = tok$1$q[add_bit$49];
        end
        if (view$49 == 2) begin
            act$49 = tok$2$q[act_bit$49];
        end
        if (view_add$49 == 2) begin
            add$49 = tok$2$q[add_bit$49];
        end
        if (view$49 == 3) begin
            act$49 = tok$3$q[act_bit$49];
        end
        if (view_add$49 == 3) begin
            add$49 = tok$3$q[add_bit$49];
        end
        if (view$49 == 4) begin
            act$49 = tok$4$q[act_bit$49];
        end
        if (view_add$49 == 4) begin
            add$49 = tok$4$q[add_bit$49];
        end
        if (view$49 == 5) begin
            act$49 = tok$5$q[act_bit$49];
        end
        if (view_add$49 == 5) begin
            add$49 = tok$5$q[add_bit$49];
        end
        act$50 = 1'b0;
        add$50 = 1'b0;
        if (view$50 == 0) begin
            act$50 = tok$0$q[act_bit$50];
        end
        if (view_add$50 == 0) begin
            add$50 = tok$0$q[add_bit$50];
        end
        if (view$50 == 1) begin
            act$50 = tok$1$q[act_bit$50];
        end
        if (view_add$50 == 1) begin
            add$50 = tok$1$q[add_bit$50];
        end
        if (view$50 == 2) begin
            act$50 = tok$2$q[act_bit$50];
        end
        if (view_add$50 == 2) begin
            add$50 = tok$2$q[add_bit$50];
        end
        if (view$50 == 3) begin
            act$50 = tok$3$q[act_bit$50];
        end
        if (view_add$50 == 3) begin
            add$50 = tok$3$q[add_bit$50];
        end
        if (view$50 == 4) begin
            act$50 = tok$4$q[act_bit$50];
        end
        if (view_add$50 == 4) begin
            add$50 = tok$4$q[add_bit$50];
        end
        if (view$50 == 5) begin
            act$50 = tok$5$q[act_bit$50];
        end
        if (view_add$50 == 5) begin
            add$50 = tok$5$q[add_bit$50];
        end
        act$51 = 1'b0;
        add$51 = 1'b0;
        if (view$51 == 0) begin
            act$51 = tok$0$q[act_bit$51];
        end
        if (view_add$51 == 0) begin
            add$51 = tok$0$q[add_bit$51];
        end
        if (view$51 == 1) begin
            act$51 = tok$1$q[act_bit$51];
        end
        if (view_add$51 == 1) begin
            add$51 = tok$1$q[add_bit$51];
        end
        if (view$51 == 2) begin
            act$51 = tok$2$q[act_bit$51];
        end
        if (view_add$51 == 2) begin
            add$51 = tok$2$q[add_bit$51];
        end
        if (view$51 == 3) begin
            act$51 = tok$3$q[act_bit$51];
        end
        if (view_add$51 == 3) begin
            add$51 = tok$3$q[add_bit$51];
        end
        if (view$51 == 4) begin
            act$51 = tok$4$q[act_bit$51];
        end
        if (view_add$51 == 4) begin
            add$51 = tok$4$q[add_bit$51];
        end
        if (view$51 == 5) begin
            act$51 = tok$5$q[act_bit$51];
        end
        if (view_add$51 == 5) begin
            add$51 = tok$5$q[add_bit$51];
        end
        act$52 = 1'b0;
        add$52 = 1'b0;
        if (view$52 == 0) begin
            act$52 = tok$0$q[act_bit$52];
        end
        if (view_add$52 == 0) begin
            add$52 = tok$0$q[add_bit$52];
        end
        if (view$52 == 1) begin
            act$52 = tok$1$q[act_bit$52];
        end
        if (view_add$52 == 1) begin
            add$52 = tok$1$q[add_bit$52];
        end
        if (view$52 == 2) begin
            act$52 = tok$2$q[act_bit$52];
        end
        if (view_add$52 == 2) begin
            add$52 = tok$2$q[add_bit$52];
        end
        if (view$52 == 3) begin
            act$52 = tok$3$q[act_bit$52];
        end
        if (view_add$52 == 3) begin
            add$52 = tok$3$q[add_bit$52];
        end
        if (view$52 == 4) begin
            act$52 = tok$4$q[act_bit$52];
        end
        if (view_add$52 == 4) begin
            add$52 = tok$4$q[add_bit$52];
        end
        if (view$52 == 5) begin
            act$52 = tok$5$q[act_bit$52];
        end
        if (view_add$52 == 5) begin
            add$52 = tok$5$q[add_bit$52];
        end
        act$53 = 1'b0;
        add$53 = 1'b0;
        if (view$53 == 0) begin
            act$53 = tok$0$q[act_bit$53];
        end
        if (view_add$53 == 0) begin
            add$53 = tok$0$q[add_bit$53];
        end
        if (view$53 == 1) begin
            act$53 = tok$1$q[act_bit$53];
        end
        if (view_add$53 == 1) begin
            add$53 = tok$1$q[add_bit$53];
        end
        if (view$53 == 2) begin
            act$53 = tok$2$q[act_bit$53];
        end
        if (view_add$53 == 2) begin
            add$53 = tok$2$q[add_bit$53];
        end
        if (view$53 == 3) begin
            act$53 = tok$3$q[act_bit$53];
        end
        if (view_add$53 == 3) begin
            add$53 = tok$3$q[add_bit$53];
        end
        if (view$53 == 4) begin
            act$53 = tok$4$q[act_bit$53];
        end
        if (view_add$53 == 4) begin
            add$53 = tok$4$q[add_bit$53];
        end
        if (view$53 == 5) begin
            act$53 = tok$5$q[act_bit$53];
        end
        if (view_add$53 == 5) begin
            add$53 = tok$5$q[add_bit$53];
        end
        act$54 = 1'b0;
        add$54 = 1'b0;
        if (view$54 == 0) begin
            act$54 = tok$0$q[act_bit$54];
        end
        if (view_add$54 == 0) begin
            add$54 = tok$0$q[add_bit$54];
        end
        if (view$54 == 1) begin
            act$54 = tok$1$q[act_bit$54];
        end
        if (view_add$54 == 1) begin
            add$54 = tok$1$q[add_bit$54];
        end
        if (view$54 == 2) begin
            act$54 = tok$2$q[act_bit$54];
        end
        if (view_add$54 == 2) begin
            add$54 = tok$2$q[add_bit$54];
        end
        if (view$54 == 3) begin
            act$54 = tok$3$q[act_bit$54];
        end
        if (view_add$54 == 3) begin
            add$54 = tok$3$q[add_bit$54];
        end
        if (view$54 == 4) begin
            act$54 = tok$4$q[act_bit$54];
        end
        if (view_add$54 == 4) begin
            add$54 = tok$4$q[add_bit$54];
        end
        if (view$54 == 5) begin
            act$54 = tok$5$q[act_bit$54];
        end
        if (view_add$54 == 5) begin
            add$54 = tok$5$q[add_bit$54];
        end
        act$55 = 1'b0;
        add$55 = 1'b0;
        if (view$55 == 0) begin
            act$55 = tok$0$q[act_bit$55];
        end
        if (view_add$55 == 0) begin
            add$55 = tok$0$q[add_bit$55];
        end
        if (view$55 == 1) begin
            act$55 = tok$1$q[act_bit$55];
        end
        if (view_add$55 == 1) begin
            add$55 = tok$1$q[add_bit$55];
        end
        if (view$55 == 2) begin
            act$55 = tok$2$q[act_bit$55];
        end
        if (view_add$55 == 2) begin
            add$55 = tok$2$q[add_bit$55];
        end
        if (view$55 == 3) begin
            act$55 = tok$3$q[act_bit$55];
        end
        if (view_add$55 == 3) begin
            add$55 = tok$3$q[add_bit$55];
        end
        if (view$55 == 4) begin
            act$55 = tok$4$q[act_bit$55];
        end
        if (view_add$55 == 4) begin
            add$55 = tok$4$q[add_bit$55];
        end
        if (view$55 == 5) begin
            act$55 = tok$5$q[act_bit$55];
        end
        if (view_add$55 == 5) begin
            add$55 = tok$5$q[add_bit$55];
        end
        act$56 = 1'b0;
        add$56 = 1'b0;
        if (view$56 == 0) begin
            act$56 = tok$0$q[act_bit$56];
        end
        if (view_add$56 == 0) begin
            add$56 = tok$0$q[add_bit$56];
        end
        if (view$56 == 1) begin
            act$56 = tok$1$q[act_bit$56];
        end
        if (view_add$56 == 1) begin
            add$56 = tok$1$q[add_bit$56];
        end
        if (view$56 == 2) begin
            act$56 = tok$2$q[act_bit$56];
        end
        if (view_add$56 == 2) begin
            add$56 = tok$2$q[add_bit$56];
        end
        if (view$56 == 3) begin
            act$56 = tok$3$q[act_bit$56];
        end
        if (view_add$56 == 3) begin
            add$56 = tok$3$q[add_bit$56];
        end
        if (view$56 == 4) begin
            act$56 = tok$4$q[act_bit$56];
        end
        if (view_add$56 == 4) begin
            add$56 = tok$4$q[add_bit$56];
        end
        if (view$56 == 5) begin
            act$56 = tok$5$q[act_bit$56];
        end
        if (view_add$56 == 5) begin
            add$56 = tok$5$q[add_bit$56];
        end
        act$57 = 1'b0;
        add$57 = 1'b0;
        if (view$57 == 0) begin
            act$57 = tok$0$q[act_bit$57];
        end
        if (view_add$57 == 0) begin
            add$57 = tok$0$q[add_bit$57];
        end
        if (view$57 == 1) begin
            act$57 = tok$1$q[act_bit$57];
        end
        if (view_add$57 == 1) begin
            add$57 = tok$1$q[add_bit$57];
        end
        if (view$57 == 2) begin
            act$57 = tok$2$q[act_bit$57];
        end
        if (view_add$57 == 2) begin
            add$57 = tok$2$q[add_bit$57];
        end
        if (view$57 == 3) begin
            act$57 = tok$3$q[act_bit$57];
        end
        if (view_add$57 == 3) begin
            add$57 = tok$3$q[add_bit$57];
        end
        if (view$57 == 4) begin
            act$57 = tok$4$q[act_bit$57];
        end
        if (view_add$57 == 4) begin
            add$57 = tok$4$q[add_bit$57];
        end
        if (view$57 == 5) begin
            act$57 = tok$5$q[act_bit$57];
        end
        if (view_add$57 == 5) begin
            add$57 = tok$5$q[add_bit$57];
        end
        act$58 = 1'b0;
        add$58 = 1'b0;
        if (view$58 == 0) begin
            act$58 = tok$0$q[act_bit$58];
        end
        if (view_add$58 == 0) begin
            add$58 = tok$0$q[add_bit$58];
        end
        if (view$58 == 1) begin
            act$58 = tok$1$q[act_bit$58];
        end
        if (view_add$58 == 1) begin
            add$58 = tok$1$q[add_bit$58];
        end
        if (view$58 == 2) begin
            act$58 = tok$2$q[act_bit$58];
        end
        if (view_add$58 == 2) begin
            add$58 = tok$2$q[add_bit$58];
        end
        if (view$58 == 3) begin
            act$58 = tok$3$q[act_bit$58];
        end
        if (view_add$58 == 3) begin
            add$58 = tok$3$q[add_bit$58];
        end
        if (view$58 == 4) begin
            act$58 = tok$4$q[act_bit$58];
        end
        if (view_add$58 == 4) begin
            add$58 = tok$4$q[add_bit$58];
        end
        if (view$58 == 5) begin
            act$58 = tok$5$q[act_bit$58];
        end
        if (view_add$58 == 5) begin
            add$58 = tok$5$q[add_bit$58];
        end
        act$59 = 1'b0;
        add$59 = 1'b0;
        if (view$59 == 0) begin
            act$59 = tok$0$q[act_bit$59];
        end
        if (view_add$59 == 0) begin
            add$59 = tok$0$q[add_bit$59];
        end
        if (view$59 == 1) begin
            act$59 = tok$1$q[act_bit$59];
        end
        if (view_add$59 == 1) begin
            add$59 = tok$1$q[add_bit$59];
        end
        if (view$59 == 2) begin
            act$59 = tok$2$q[act_bit$59];
        end
        if (view_add$59 == 2) begin
            add$59 = tok$2$q[add_bit$59];
        end
        if (view$59 == 3) begin
            act$59 = tok$3$q[act_bit$59];
        end
        if (view_add$59 == 3) begin
            add$59 = tok$3$q[add_bit$59];
        end
        if (view$59 == 4) begin
            act$59 = tok$4$q[act_bit$59];
        end
        if (view_add$59 == 4) begin
            add$59 = tok$4$q[add_bit$59];
        end
        if (view$59 == 5) begin
            act$59 = tok$5$q[act_bit$59];
        end
        if (view_add$59 == 5) begin
            add$59 = tok$5$q[add_bit$59];
        end
        act$60 = 1'b0;
        add$60 = 1'b0;
        if (view$60 == 0) begin
            act$60 = tok$0$q[act_bit$60];
        end
        if (view_add$60 == 0) begin
            add$60 = tok$0$q[add_bit$60];
        end
        if (view$60 == 1) begin
            act$60 = tok$1$q[act_bit$60];
        end
        if (view_add$60 == 1) begin
            add$60 = tok$1$q[add_bit$60];
        end
        if (view$60 == 2) begin
            act$60 = tok$2$q[act_bit$60];
        end
        if (view_add$60 == 2) begin
            add$60 = tok$2$q[add_bit$60];
        end
        if (view$60 == 3) begin
            act$60 = tok$3$q[act_bit$60];
        end
        if (view_add$60 == 3) begin
            add$60 = tok$3$q[add_bit$60];
        end
        if (view$60 == 4) begin
            act$60 = tok$4$q[act_bit$60];
        end
        if (view_add$60 == 4) begin
            add$60 = tok$4$q[add_bit$60];
        end
        if (view$60 == 5) begin
            act$60 = tok$5$q[act_bit$60];
        end
        if (view_add$60 == 5) begin
            add$60 = tok$5$q[add_bit$60];
        end
        act$61 = 1'b0;
        add$61 = 1'b0;
        if (view$61 == 0) begin
            act$61 = tok$0$q[act_bit$61];
        end
        if (view_add$61 == 0) begin
            add$61 = tok$0$q[add_bit$61];
        end
        if (view$61 == 1) begin
            act$61 = tok$1$q[act_bit$61];
        end
        if (view_add$61 == 1) begin
            add$61 = tok$1$q[add_bit$61];
        end
        if (view$61 == 2) begin
            act$61 = tok$2$q[act_bit$61];
        end
        if (view_add$61 == 2) begin
            add$61 = tok$2$q[add_bit$61];
        end
        if (view$61 == 3) begin
            act$61 = tok$3$q[act_bit$61];
        end
        if (view_add$61 == 3) begin
            add$61 = tok$3$q[add_bit$61];
        end
        if (view$61 == 4) begin
            act$61 = tok$4$q[act_bit$61];
        end
        if (view_add$61 == 4) begin
            add$61 = tok$4$q[add_bit$61];
        end
        if (view$61 == 5) begin
            act$61 = tok$5$q[act_bit$61];
        end
        if (view_add$61 == 5) begin
            add$61 = tok$5$q[add_bit$61];
        end
        act$62 = 1'b0;
        add$62 = 1'b0;
        if (view$62 == 0) begin
            act$62 = tok$0$q[act_bit$62];
        end
        if (view_add$62 == 0) begin
            add$62 = tok$0$q[add_bit$62];
        end
        if (view$62 == 1) begin
            act$62 = tok$1$q[act_bit$62];
        end
        if (view_add$62 == 1) begin
            add$62 = tok$1$q[add_bit$62];
        end
        if (view$62 == 2) begin
            act$62 = tok$2$q[act_bit$62];
        end
        if (view_add$62 == 2) begin
            add$62 = tok$2$q[add_bit$62];
        end
        if (view$62 == 3) begin
            act$62 = tok$3$q[act_bit$62];
        end
        if (view_add$62 == 3) begin
            add$62 = tok$3$q[add_bit$62];
        end
        if (view$62 == 4) begin
            act$62 = tok$4$q[act_bit$62];
        end
        if (view_add$62 == 4) begin
            add$62 = tok$4$q[add_bit$62];
        end
        if (view$62 == 5) begin
            act$62 = tok$5$q[act_bit$62];
        end
        if (view_add$62 == 5) begin
            add$62 = tok$5$q[add_bit$62];
        end
        act$63 = 1'b0;
        add$63 = 1'b0;
        if (view$63 == 0) begin
            act$63 = tok$0$q[act_bit$63];
        end
        if (view_add$63 == 0) begin
            add$63 = tok$0$q[add_bit$63];
        end
        if (view$63 == 1) begin
            act$63 = tok$1$q[act_bit$63];
        end
        if (view_add$63 == 1) begin
            add$63 = tok$1$q[add_bit$63];
        end
        if (view$63 == 2) begin
            act$63 = tok$2$q[act_bit$63];
        end
        if (view_add$63 == 2) begin
            add$63 = tok$2$q[add_bit$63];
        end
        if (view$63 == 3) begin
            act$63 = tok$3$q[act_bit$63];
        end
        if (view_add$63 == 3) begin
            add$63 = tok$3$q[add_bit$63];
        end
        if (view$63 == 4) begin
            act$63 = tok$4$q[act_bit$63];
        end
        if (view_add$63 == 4) begin
            add$63 = tok$4$q[add_bit$63];
        end
        if (view$63 == 5) begin
            act$63 = tok$5$q[act_bit$63];
        end
        if (view_add$63 == 5) begin
            add$63 = tok$5$q[add_bit$63];
        end
        at_norm = tok$0$q[norm_bit] & run;
        at_iss$0 = tok$0$q[iss_bit$0] & run;
        at_res$0 = 1'b0;
        if (view_res$0 == 0) begin
            at_res$0 = tok$0$q[res_bit$0] & run;
        end
        if (view_res$0 == 1) begin
            at_res$0 = tok$1$q[res_bit$0] & run;
        end
        if (view_res$0 == 2) begin
            at_res$0 = tok$2$q[res_bit$0] & run;
        end
        if (view_res$0 == 3) begin
            at_res$0 = tok$3$q[res_bit$0] & run;
        end
        if (view_res$0 == 4) begin
            at_res$0 = tok$4$q[res_bit$0] & run;
        end
        if (view_res$0 == 5) begin
            at_res$0 = tok$5$q[res_bit$0] & run;
        end
        at_iss$1 = tok$0$q[iss_bit$1] & run;
        at_res$1 = 1'b0;
        if (view_res$1 == 0) begin
            at_res$1 = tok$0$q[res_bit$1] & run;
        end
        if (view_res$1 == 1) begin
            at_res$1 = tok$1$q[res_bit$1] & run;
        end
        if (view_res$1 == 2) begin
            at_res$1 = tok$2$q[res_bit$1] & run;
        end
        if (view_res$1 == 3) begin
            at_res$1 = tok$3$q[res_bit$1] & run;
        end
        if (view_res$1 == 4) begin
            at_res$1 = tok$4$q[res_bit$1] & run;
        end
        if (view_res$1 == 5) begin
            at_res$1 = tok$5$q[res_bit$1] & run;
        end
        at_iss$2 = tok$0$q[iss_bit$2] & run;
        at_res$2 = 1'b0;
        if (view_res$2 == 0) begin
            at_res$2 = tok$0$q[res_bit$2] & run;
        end
        if (view_res$2 == 1) begin
            at_res$2 = tok$1$q[res_bit$2] & run;
        end
        if (view_res$2 == 2) begin
            at_res$2 = tok$2$q[res_bit$2] & run;
        end
        if (view_res$2 == 3) begin
            at_res$2 = tok$3$q[res_bit$2] & run;
        end
        if (view_res$2 == 4) begin
            at_res$2 = tok$4$q[res_bit$2] & run;
        end
        if (view_res$2 == 5) begin
            at_res$2 = tok$5$q[res_bit$2] & run;
        end
        at_iss$3 = tok$0$q[iss_bit$3] & run;
        at_res$3 = 1'b0;
        if (view_res$3 == 0) begin
            at_res$3 = tok$0$q[res_bit$3] & run;
        end
        if (view_res$3 == 1) begin
            at_res$3 = tok$1$q[res_bit$3] & run;
        end
        if (view_res$3 == 2) begin
            at_res$3 = tok$2$q[res_bit$3] & run;
        end
        if (view_res$3 == 3) begin
            at_res$3 = tok$3$q[res_bit$3] & run;
        end
        if (view_res$3 == 4) begin
            at_res$3 = tok$4$q[res_bit$3] & run;
        end
        if (view_res$3 == 5) begin
            at_res$3 = tok$5$q[res_bit$3] & run;
        end
        at_iss$4 = tok$0$q[iss_bit$4] & run;
        at_res$4 = 1'b0;
        if (view_res$4 == 0) begin
            at_res$4 = tok$0$q[res_bit$4] & run;
        end
        if (view_res$4 == 1) begin
            at_res$4 = tok$1$q[res_bit$4] & run;
        end
        if (view_res$4 == 2) begin
            at_res$4 = tok$2$q[res_bit$4] & run;
        end
        if (view_res$4 == 3) begin
            at_res$4 = tok$3$q[res_bit$4] & run;
        end
        if (view_res$4 == 4) begin
            at_res$4 = tok$4$q[res_bit$4] & run;
        end
        if (view_res$4 == 5) begin
            at_res$4 = tok$5$q[res_bit$4] & run;
        end
        at_iss$5 = tok$0$q[iss_bit$5] & run;
        at_res$5 = 1'b0;
        if (view_res$5 == 0) begin
            at_res$5 = tok$0$q[res_bit$5] & run;
        end
        if (view_res$5 == 1) begin
            at_res$5 = tok$1$q[res_bit$5] & run;
        end
        if (view_res$5 == 2) begin
            at_res$5 = tok$2$q[res_bit$5] & run;
        end
        if (view_res$5 == 3) begin
            at_res$5 = tok$3$q[res_bit$5] & run;
        end
        if (view_res$5 == 4) begin
            at_res$5 = tok$4$q[res_bit$5] & run;
        end
        if (view_res$5 == 5) begin
            at_res$5 = tok$5$q[res_bit$5] & run;
        end
        at_iss$6 = tok$0$q[iss_bit$6] & run;
        at_res$6 = 1'b0;
        if (view_res$6 == 0) begin
            at_res$6 = tok$0$q[res_bit$6] & run;
        end
        if (view_res$6 == 1) begin
            at_res$6 = tok$1$q[res_bit$6] & run;
        end
        if (view_res$6 == 2) begin
            at_res$6 = tok$2$q[res_bit$6] & run;
        end
        if (view_res$6 == 3) begin
            at_res$6 = tok$3$q[res_bit$6] & run;
        end
        if (view_res$6 == 4) begin
            at_res$6 = tok$4$q[res_bit$6] & run;
        end
        if (view_res$6 == 5) begin
            at_res$6 = tok$5$q[res_bit$6] & run;
        end
        at_handover = 1'b0;
        if (view_handover == 0) begin
            at_handover = tok$0$q[handover_bit] & run;
        end
        if (view_handover == 1) begin
            at_handover = tok$1$q[handover_bit] & run;
        end
        if (view_handover == 2) begin
            at_handover = tok$2$q[handover_bit] & run;
        end
        if (view_handover == 3) begin
            at_handover = tok$3$q[handover_bit] & run;
        end
        if (view_handover == 4) begin
            at_handover = tok$4$q[handover_bit] & run;
        end
        if (view_handover == 5) begin
            at_handover = tok$5$q[handover_bit] & run;
        end
        busy_n = 1'b0;
        if (|tok_n$0) begin
            busy_n = 1'b1;
        end
        if (|tok_n$1) begin
            busy_n = 1'b1;
        end
        if (|tok_n$2) begin
            busy_n = 1'b1;
        end
        if (|tok_n$3) begin
            busy_n = 1'b1;
        end
        if (|tok_n$4) begin
            busy_n = 1'b1;
        end
        if (|tok_n$5) begin
            busy_n = 1'b1;
        end
        off_grid_n = off_grid_r$q;
        if (run) begin
            off_grid_n = take | (phase$q != ii_m1);
        end
        busy_r$d = busy_n;
        off_grid_r$d = off_grid_n;
        gate_r$d = busy_n & off_grid_n;
        idle = ~busy_r$q;
        geometry$vx$0 = inp$v0_x;
        geometry$vy$0 = inp$v0_y;
        geometry$vz$0 = inp$v0_z;
        geometry$vc$0 = inp$v0_c0;
        geometry$vc$1 = inp$v0_c1;
        geometry$vc$2 = inp$v0_c2;
        geometry$vx$1 = inp$v1_x;
        geometry$vy$1 = inp$v1_y;
        geometry$vz$1 = inp$v1_z;
        geometry$vc$3 = inp$v1_c0;
        geometry$vc$4 = inp$v1_c1;
        geometry$vc$5 = inp$v1_c2;
        geometry$vx$2 = inp$v2_x;
        geometry$vy$2 = inp$v2_y;
        geometry$vz$2 = inp$v2_z;
        geometry$vc$6 = inp$v2_c0;
        geometry$vc$7 = inp$v2_c1;
        geometry$vc$8 = inp$v2_c2;
        geometry$crosses = inp$crosses;
        g0$word = geo$0$q;
        g0$maj_left = maj_left$0;
        g0$start_x$0 = x$0$q;
        g0$start_x$1 = x$1$q;
        g0$start_x$2 = x$2$q;
        g1$word = geo$1$q;
        g1$maj_left = maj_left$1;
        g1$start_x$0 = x$3$q;
        g1$start_x$1 = x$4$q;
        g1$start_x$2 = x$5$q;
        g2$word = geo$2$q;
        g2$maj_left = maj_left$2;
        g2$start_x$0 = x$6$q;
        g2$start_x$1 = x$7$q;
        g2$start_x$2 = x$8$q;
        g3$word = geo$3$q;
        g3$maj_left = maj_left$3;
        g3$start_x$0 = x$9$q;
        g3$start_x$1 = x$10$q;
        g3$start_x$2 = x$11$q;
        g4$word = geo$4$q;
        g4$maj_left = maj_left$4;
        g4$start_x$0 = x$12$q;
        g4$start_x$1 = x$13$q;
        g4$start_x$2 = x$14$q;
        g5$word = geo$5$q;
        g5$maj_left = maj_left$5;
        g5$start_x$0 = x$15$q;
        g5$start_x$1 = x$16$q;
        g5$start_x$2 = x$17$q;
        area_abs = area$q;
        if (area$q[area_msb]) begin
            area_abs = ((32'h0) & 34'h3ffffffff) - area$q;
        end
        abs_p = ((area_abs) & 36'hfffffffff);
        nib_any$0 = 1'b0;
        nib_pos$0 = 32'h0;
        if (abs_p[32'h4 * 0 + 0]) begin
            nib_any$0 = 1'b1;
            nib_pos$0 = bit_index$0;
        end
        if (abs_p[32'h4 * 0 + 1]) begin
            nib_any$0 = 1'b1;
            nib_pos$0 = bit_index$1;
        end
        if (abs_p[32'h4 * 0 + 2]) begin
            nib_any$0 = 1'b1;
            nib_pos$0 = bit_index$2;
        end
        if (abs_p[32'h4 * 0 + 3]) begin
            nib_any$0 = 1'b1;
            nib_pos$0 = bit_index$3;
        end
        nib_sh$0 = recip_top - nib_pos$0;
        nib_any$1 = 1'b0;
        nib_pos$1 = 32'h0;
        if (abs_p[32'h4 * 1 + 0]) begin
            nib_any$1 = 1'b1;
            nib_pos$1 = bit_index$4;
        end
        if (abs_p[32'h4 * 1 + 1]) begin
            nib_any$1 = 1'b1;
            nib_pos$1 = bit_index$5;
        end
        if (abs_p[32'h4 * 1 + 2]) begin
            nib_any$1 = 1'b1;
            nib_pos$1 = bit_index$6;
        end
        if (abs_p[32'h4 * 1 + 3]) begin
            nib_any$1 = 1'b1;
            nib_pos$1 = bit_index$7;
        end
        nib_sh$1 = recip_top - nib_pos$1;
        nib_any$2 = 1'b0;
        nib_pos$2 = 32'h0;
        if (abs_p[32'h4 * 2 + 0]) begin
            nib_any$2 = 1'b1;
            nib_pos$2 = bit_index$8;
        end
        if (abs_p[32'h4 * 2 + 1]) begin
            nib_any$2 = 1'b1;
            nib_pos$2 = bit_index$9;
        end
        if (abs_p[32'h4 * 2 + 2]) begin
            nib_any$2 = 1'b1;
            nib_pos$2 = bit_index$10;
        end
        if (abs_p[32'h4 * 2 + 3]) begin
            nib_any$2 = 1'b1;
            nib_pos$2 = bit_index$11;
        end
        nib_sh$2 = recip_top - nib_pos$2;
        nib_any$3 = 1'b0;
        nib_pos$3 = 32'h0;
        if (abs_p[32'h4 * 3 + 0]) begin
            nib_any$3 = 1'b1;
            nib_pos$3 = bit_index$12;
        end
        if (abs_p[32'h4 * 3 + 1]) begin
            nib_any$3 = 1'b1;
            nib_pos$3 = bit_index$13;
        end
        if (abs_p[32'h4 * 3 + 2]) begin
            nib_any$3 = 1'b1;
            nib_pos$3 = bit_index$14;
        end
        if (abs_p[32'h4 * 3 + 3]) begin
            nib_any$3 = 1'b1;
            nib_pos$3 = bit_index$15;
        end
        nib_sh$3 = recip_top - nib_pos$3;
        nib_any$4 = 1'b0;
        nib_pos$4 = 32'h0;
        if (abs_p[32'h4 * 4 + 0]) begin
            nib_any$4 = 1'b1;
            nib_pos$4 = bit_index$16;
        end
        if (abs_p[32'h4 * 4 + 1]) begin
            nib_any$4 = 1'b1;
            nib_pos$4 = bit_index$17;
        end
        if (abs_p[32'h4 * 4 + 2]) begin
            nib_any$4 = 1'b1;
            nib_pos$4 = bit_index$18;
        end
        if (abs_p[32'h4 * 4 + 3]) begin
            nib_any$4 = 1'b1;
            nib_pos$4 = bit_index$19;
        end
        nib_sh$4 = recip_top - nib_pos$4;
        nib_any$5 = 1'b0;
        nib_pos$5 = 32'h0;
        if (abs_p[32'h4 * 5 + 0]) begin
            nib_any$5 = 1'b1;
            nib_pos$5 = bit_index$20;
        end
        if (abs_p[32'h4 * 5 + 1]) begin
            nib_any$5 = 1'b1;
            nib_pos$5 = bit_index$21;
        end
        if (abs_p[32'h4 * 5 + 2]) begin
            nib_any$5 = 1'b1;
            nib_pos$5 = bit_index$22;
        end
        if (abs_p[32'h4 * 5 + 3]) begin
            nib_any$5 = 1'b1;
            nib_pos$5 = bit_index$23;
        end
        nib_sh$5 = recip_top - nib_pos$5;
        nib_any$6 = 1'b0;
        nib_pos$6 = 32'h0;
        if (abs_p[32'h4 * 6 + 0]) begin
            nib_any$6 = 1'b1;
            nib_pos$6 = bit_index$24;
        end
        if (abs_p[32'h4 * 6 + 1]) begin
            nib_any$6 = 1'b1;
            nib_pos$6 = bit_index$25;
        end
        if (abs_p[32'h4 * 6 + 2]) begin
            nib_any$6 = 1'b1;
            nib_pos$6 = bit_index$26;
        end
        if (abs_p[32'h4 * 6 + 3]) begin
            nib_any$6 = 1'b1;
            nib_pos$6 = bit_index$27;
        end
        nib_sh$6 = recip_top - nib_pos$6;
        nib_any$7 = 1'b0;
        nib_pos$7 = 32'h0;
        if (abs_p[32'h4 * 7 + 0]) begin
            nib_any$7 = 1'b1;
            nib_pos$7 = bit_index$28;
        end
        if (abs_p[32'h4 * 7 + 1]) begin
            nib_any$7 = 1'b1;
            nib_pos$7 = bit_index$29;
        end
        if (abs_p[32'h4 * 7 + 2]) begin
            nib_any$7 = 1'b1;
            nib_pos$7 = bit_index$30;
        end
        if (abs_p[32'h4 * 7 + 3]) begin
            nib_any$7 = 1'b1;
            nib_pos$7 = bit_index$31;
        end
        nib_sh$7 = recip_top - nib_pos$7;
        nib_any$8 = 1'b0;
        nib_pos$8 = 32'h0;
        if (abs_p[32'h4 * 8 + 0]) begin
            nib_any$8 = 1'b1;
            nib_pos$8 = bit_index$32;
        end
        if (abs_p[32'h4 * 8 + 1]) begin
            nib_any$8 = 1'b1;
            nib_pos$8 = bit_index$33;
        end
        if (abs_p[32'h4 * 8 + 2]) begin
            nib_any$8 = 1'b1;
            nib_pos$8 = bit_index$34;
        end
        if (abs_p[32'h4 * 8 + 3]) begin
            nib_any$8 = 1'b1;
            nib_pos$8 = bit_index$35;
        end
        nib_sh$8 = recip_top - nib_pos$8;
        exp_c = 32'h0;
        nsh_c = recip_top;
        if (nib_any$0) begin
            exp_c = nib_pos$0;
            nsh_c = nib_sh$0;
        end
        if (nib_any$1) begin
            exp_c = nib_pos$1;
            nsh_c = nib_sh$1;
        end
        if (nib_any$2) begin
            exp_c = nib_pos$2;
            nsh_c = nib_sh$2;
        end
        if (nib_any$3) begin
            exp_c = nib_pos$3;
            nsh_c = nib_sh$3;
        end
        if (nib_any$4) begin
            exp_c = nib_pos$4;
            nsh_c = nib_sh$4;
        end
        if (nib_any$5) begin
            exp_c = nib_pos$5;
            nsh_c = nib_sh$5;
        end
        if (nib_any$6) begin
            exp_c = nib_pos$6;
            nsh_c = nib_sh$6;
        end
        if (nib_any$7) begin
            exp_c = nib_pos$7;
            nsh_c = nib_sh$7;
        end
        if (nib_any$8) begin
            exp_c = nib_pos$8;
            nsh_c = nib_sh$8;
        end
        if (at_norm) begin
            norm$d = area_abs;
            nsh$d = nsh_c;
            exp$0$d = exp_c;
        end
        norm_d = norm$q << nsh$q;
        div$out_ready = 1'b1;
        div$hold = ~run;
        div$inp_valid = div_v$q;
        div$inp_n = div_n$q;
        div$inp_d = div_d$q;
        div_v$d = div_v$q;
        div_n$d = div_n$q;
        div_d$d = div_d$q;
        if (run) begin
            div_v$d = 1'b0;
            div_n$d = 32'h0;
            div_d$d = 32'h1;
        end
        if (at_iss$0) begin
            div_v$d = 1'b1;
            div_n$d = recip_n;
            div_d$d = norm_d;
        end
        if (at_iss$1) begin
            div_v$d = 1'b1;
            if (g0$used$0) begin
                div_n$d = num$0$q[(32'h0)+:(58)];
                div_d$d = g0$ed16$0;
            end
        end
        if (at_iss$2) begin
            div_v$d = 1'b1;
            if (g0$step$0) begin
                div_n$d = g0$edx$0[(32'h0)+:(58)];
                div_d$d = g0$edy_d$0;
            end
        end
        if (at_iss$3) begin
            div_v$d = 1'b1;
            if (g0$used$1) begin
                div_n$d = num$1$q[(32'h0)+:(58)];
                div_d$d = g0$ed16$1;
            end
        end
        if (at_iss$4) begin
            div_v$d = 1'b1;
            if (g0$step$1) begin
                div_n$d = g0$edx$1[(32'h0)+:(58)];
                div_d$d = g0$edy_d$1;
            end
        end
        if (at_iss$5) begin
            div_v$d = 1'b1;
            if (g0$used$2) begin
                div_n$d = num$2$q[(32'h0)+:(58)];
                div_d$d = g0$ed16$2;
            end
        end
        if (at_iss$6) begin
            div_v$d = 1'b1;
            if (g0$step$2) begin
                div_n$d = g0$edx$2[(32'h0)+:(58)];
                div_d$d = g0$edy_d$2;
            end
        end
        q_n = ((div$out_q[(32'h0)+:(19)]) & 19'h7ffff);
        if (div$out_q[q_msb]) begin
            q_n = ((div$out_q[(32'h0)+:(19)]) & 19'h7ffff) | q_ext;
        end
        r_pos = div$out_r != 32'h0;
        exp_r = exp$0$q;
        if (view_res$0 == 1) begin
            exp_r = exp$1$q;
        end
        if (view_res$0 == 2) begin
            exp_r = exp$2$q;
        end
        if (view_res$0 == 3) begin
            exp_r = exp$3$q;
        end
        if (view_res$0 == 4) begin
            exp_r = exp$4$q;
        end
        if (view_res$0 == 5) begin
            exp_r = exp$5$q;
        end
        lsh = eq_shift - exp_r;
        if (at_res$0) begin
            rsh$d = exp_r - eq_shift;
            left$d = exp_r <= eq_shift;
            mant_s$d = ((div$out_q[(32'h0)+:(25)]) & 57'h1ffffffffffffff);
            if (exp_r <= eq_shift) begin
                mant_s$d = ((div$out_q[(32'h0)+:(25)]) & 57'h1ffffffffffffff) << lsh;
            end
        end
        xi$0 = g0$xi$0;
        ed$0 = g0$ed16$0[(32'h0)+:(21)];
        if (view_res$1 == 32'h1) begin
            xi$0 = g1$xi$0;
            ed$0 = g1$ed16$0[(32'h0)+:(21)];
        end
        if (view_res$1 == 32'h2) begin
            xi$0 = g2$xi$0;
            ed$0 = g2$ed16$0[(32'h0)+:(21)];
        end
        if (view_res$1 == 32'h3) begin
            xi$0 = g3$xi$0;
            ed$0 = g3$ed16$0[(32'h0)+:(21)];
        end
        if (view_res$1 == 32'h4) begin
            xi$0 = g4$xi$0;
            ed$0 = g4$ed16$0[(32'h0)+:(21)];
        end
        if (view_res$1 == 32'h5) begin
            xi$0 = g5$xi$0;
            ed$0 = g5$ed16$0[(32'h0)+:(21)];
        end
        if (at_res$1 & (view_res_w$1 == 0)) begin
            x$0$d = xi$0 + q_n + r_pos;
            r$0$d = 32'h0;
            if (r_pos) begin
                r$0$d = ed$0 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$2 & (view_res_w$2 == 0)) begin
            q$0$d = q_n;
            rho$0$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$1 & (view_res_w$1 == 1)) begin
            x$3$d = xi$0 + q_n + r_pos;
            r$3$d = 32'h0;
            if (r_pos) begin
                r$3$d = ed$0 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$2 & (view_res_w$2 == 1)) begin
            q$3$d = q_n;
            rho$3$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$1 & (view_res_w$1 == 2)) begin
            x$6$d = xi$0 + q_n + r_pos;
            r$6$d = 32'h0;
            if (r_pos) begin
                r$6$d = ed$0 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$2 & (view_res_w$2 == 2)) begin
            q$6$d = q_n;
            rho$6$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$1 & (view_res_w$1 == 3)) begin
            x$9$d = xi$0 + q_n + r_pos;
            r$9$d = 32'h0;
            if (r_pos) begin
                r$9$d = ed$0 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$2 & (view_res_w$2 == 3)) begin
            q$9$d = q_n;
            rho$9$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$1 & (view_res_w$1 == 4)) begin
            x$12$d = xi$0 + q_n + r_pos;
            r$12$d = 32'h0;
            if (r_pos) begin
                r$12$d = ed$0 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$2 & (view_res_w$2 == 4)) begin
            q$12$d = q_n;
            rho$12$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$1 & (view_res_w$1 == 5)) begin
            x$15$d = xi$0 + q_n + r_pos;
            r$15$d = 32'h0;
            if (r_pos) begin
                r$15$d = ed$0 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$2 & (view_res_w$2 == 5)) begin
            q$15$d = q_n;
            rho$15$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        xi$1 = g0$xi$1;
        ed$1 = g0$ed16$1[(32'h0)+:(21)];
        if (view_res$3 == 32'h1) begin
            xi$1 = g1$xi$1;
            ed$1 = g1$ed16$1[(32'h0)+:(21)];
        end
        if (view_res$3 == 32'h2) begin
            xi$1 = g2$xi$1;
            ed$1 = g2$ed16$1[(32'h0)+:(21)];
        end
        if (view_res$3 == 32'h3) begin
            xi$1 = g3$xi$1;
            ed$1 = g3$ed16$1[(32'h0)+:(21)];
        end
        if (view_res$3 == 32'h4) begin
            xi$1 = g4$xi$1;
            ed$1 = g4$ed16$1[(32'h0)+:(21)];
        end
        if (view_res$3 == 32'h5) begin
            xi$1 = g5$xi$1;
            ed$1 = g5$ed16$1[(32'h0)+:(21)];
        end
        if (at_res$3 & (view_res_w$3 == 0)) begin
            x$1$d = xi$1 + q_n + r_pos;
            r$1$d = 32'h0;
            if (r_pos) begin
                r$1$d = ed$1 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$4 & (view_res_w$4 == 0)) begin
            q$1$d = q_n;
            rho$1$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$3 & (view_res_w$3 == 1)) begin
            x$4$d = xi$1 + q_n + r_pos;
            r$4$d = 32'h0;
            if (r_pos) begin
                r$4$d = ed$1 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$4 & (view_res_w$4 == 1)) begin
            q$4$d = q_n;
            rho$4$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$3 & (view_res_w$3 == 2)) begin
            x$7$d = xi$1 + q_n + r_pos;
            r$7$d = 32'h0;
            if (r_pos) begin
                r$7$d = ed$1 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$4 & (view_res_w$4 == 2)) begin
            q$7$d = q_n;
            rho$7$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$3 & (view_res_w$3 == 3)) begin
            x$10$d = xi$1 + q_n + r_pos;
            r$10$d = 32'h0;
            if (r_pos) begin
                r$10$d = ed$1 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$4 & (view_res_w$4 == 3)) begin
            q$10$d = q_n;
            rho$10$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$3 & (view_res_w$3 == 4)) begin
            x$13$d = xi$1 + q_n + r_pos;
            r$13$d = 32'h0;
            if (r_pos) begin
                r$13$d = ed$1 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$4 & (view_res_w$4 == 4)) begin
            q$13$d = q_n;
            rho$13$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$3 & (view_res_w$3 == 5)) begin
            x$16$d = xi$1 + q_n + r_pos;
            r$16$d = 32'h0;
            if (r_pos) begin
                r$16$d = ed$1 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$4 & (view_res_w$4 == 5)) begin
            q$16$d = q_n;
            rho$16$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        xi$2 = g0$xi$2;
        ed$2 = g0$ed16$2[(32'h0)+:(21)];
        if (view_res$5 == 32'h1) begin
            xi$2 = g1$xi$2;
            ed$2 = g1$ed16$2[(32'h0)+:(21)];
        end
        if (view_res$5 == 32'h2) begin
            xi$2 = g2$xi$2;
            ed$2 = g2$ed16$2[(32'h0)+:(21)];
        end
        if (view_res$5 == 32'h3) begin
            xi$2 = g3$xi$2;
            ed$2 = g3$ed16$2[(32'h0)+:(21)];
        end
        if (view_res$5 == 32'h4) begin
            xi$2 = g4$xi$2;
            ed$2 = g4$ed16$2[(32'h0)+:(21)];
        end
        if (view_res$5 == 32'h5) begin
            xi$2 = g5$xi$2;
            ed$2 = g5$ed16$2[(32'h0)+:(21)];
        end
        if (at_res$5 & (view_res_w$5 == 0)) begin
            x$2$d = xi$2 + q_n + r_pos;
            r$2$d = 32'h0;
            if (r_pos) begin
                r$2$d = ed$2 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$6 & (view_res_w$6 == 0)) begin
            q$2$d = q_n;
            rho$2$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$5 & (view_res_w$5 == 1)) begin
            x$5$d = xi$2 + q_n + r_pos;
            r$5$d = 32'h0;
            if (r_pos) begin
                r$5$d = ed$2 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$6 & (view_res_w$6 == 1)) begin
            q$5$d = q_n;
            rho$5$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$5 & (view_res_w$5 == 2)) begin
            x$8$d = xi$2 + q_n + r_pos;
            r$8$d = 32'h0;
            if (r_pos) begin
                r$8$d = ed$2 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$6 & (view_res_w$6 == 2)) begin
            q$8$d = q_n;
            rho$8$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$5 & (view_res_w$5 == 3)) begin
            x$11$d = xi$2 + q_n + r_pos;
            r$11$d = 32'h0;
            if (r_pos) begin
                r$11$d = ed$2 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$6 & (view_res_w$6 == 3)) begin
            q$11$d = q_n;
            rho$11$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$5 & (view_res_w$5 == 4)) begin
            x$14$d = xi$2 + q_n + r_pos;
            r$14$d = 32'h0;
            if (r_pos) begin
                r$14$d = ed$2 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$6 & (view_res_w$6 == 4)) begin
            q$14$d = q_n;
            rho$14$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$5 & (view_res_w$5 == 5)) begin
            x$17$d = xi$2 + q_n + r_pos;
            r$17$d = 32'h0;
            if (r_pos) begin
                r$17$d = ed$2 - div$out_r[(32'h0)+:(21)];
            end
        end
        if (at_res$6 & (view_res_w$6 == 5)) begin
            q$17$d = q_n;
            rho$17$d = div$out_r[(32'h0)+:(21)] << frac;
        end
        if (at_res$0 & (view_res_w$0 == 0)) begin
            mant$0$d = div$out_q[(32'h0)+:(25)];
        end
        if (at_res$0 & (view_res_w$0 == 1)) begin
            mant$1$d = div$out_q[(32'h0)+:(25)];
        end
        if (at_res$0 & (view_res_w$0 == 2)) begin
            mant$2$d = div$out_q[(32'h0)+:(25)];
        end
        if (at_res$0 & (view_res_w$0 == 3)) begin
            mant$3$d = div$out_q[(32'h0)+:(25)];
        end
        if (at_res$0 & (view_res_w$0 == 4)) begin
            mant$4$d = div$out_q[(32'h0)+:(25)];
        end
        if (at_res$0 & (view_res_w$0 == 5)) begin
            mant$5$d = div$out_q[(32'h0)+:(25)];
        end
        mul$0$a = 32'h0;
        mul$0$b = 32'h0;
        mul$1$a = 32'h0;
        mul$1$b = 32'h0;
        mul$2$a = 32'h0;
        mul$2$b = 32'h0;
        mul$3$a = 32'h0;
        mul$3$b = 32'h0;
        mul$4$a = 32'h0;
        mul$4$b = 32'h0;
        mul$5$a = 32'h0;
        mul$5$b = 32'h0;
        mul$6$a = 32'h0;
        mul$6$b = 32'h0;
        pa$0 = 32'h0;
        pa$1 = 32'h0;
        pn$0 = 32'h0;
        pn$1 = 32'h0;
        pn$2 = 32'h0;
        pn$3 = 32'h0;
        pn$4 = 32'h0;
        pn$5 = 32'h0;
        pe$0 = 32'h0;
        pe$1 = 32'h0;
        pe$2 = 32'h0;
        pe$3 = 32'h0;
        pg$0 = 32'h0;
        pg$1 = 32'h0;
        pg$2 = 32'h0;
        pg$3 = 32'h0;
        pg$4 = 32'h0;
        pg$5 = 32'h0;
        pg$6 = 32'h0;
        pg$7 = 32'h0;
        pg$8 = 32'h0;
        pg$9 = 32'h0;
        pg$10 = 32'h0;
        pg$11 = 32'h0;
        pg$12 = 32'h0;
        pg$13 = 32'h0;
        pg$14 = 32'h0;
        pg$15 = 32'h0;
        ps$0 = 32'h0;
        ps$1 = 32'h0;
        ps$2 = 32'h0;
        ps$3 = 32'h0;
        ps$4 = 32'h0;
        ps$5 = 32'h0;
        ps$6 = 32'h0;
        ps$7 = 32'h0;
        ps$8 = 32'h0;
        ps$9 = 32'h0;
        ps$10 = 32'h0;
        ps$11 = 32'h0;
        ps$12 = 32'h0;
        ps$13 = 32'h0;
        ps$14 = 32'h0;
        ps$15 = 32'h0;
        ps$16 = 32'h0;
        ps$17 = 32'h0;
        ps$18 = 32'h0;
        ps$19 = 32'h0;
        ps$20 = 32'h0;
        ps$21 = 32'h0;
        ps$22 = 32'h0;
        ps$23 = 32'h0;
        ps$24 = 32'h0;
        ps$25 = 32'h0;
        ps$26 = 32'h0;
        ps$27 = 32'h0;
        ps$28 = 32'h0;
        ps$29 = 32'h0;
        ps$30 = 32'h0;
        ps$31 = 32'h0;
        ps$32 = 32'h0;
        ps$33 = 32'h0;
        ps$34 = 32'h0;
        ps$35 = 32'h0;
        delta$0 = g0$kdx$0[(32'h0)+:(19)];
        delta$2 = g0$kdy$0[(32'h0)+:(19)];
        delta$4 = g1$kdx$0[(32'h0)+:(19)];
        delta$6 = g1$kdy$0[(32'h0)+:(19)];
        delta$8 = g2$kdx$0[(32'h0)+:(19)];
        delta$10 = g2$kdy$0[(32'h0)+:(19)];
        delta$12 = g3$kdx$0[(32'h0)+:(19)];
        delta$14 = g3$kdy$0[(32'h0)+:(19)];
        delta$16 = g4$kdx$0[(32'h0)+:(19)];
        delta$18 = g4$kdy$0[(32'h0)+:(19)];
        delta$20 = g5$kdx$0[(32'h0)+:(19)];
        delta$22 = g5$kdy$0[(32'h0)+:(19)];
        delta$1 = g0$kdx$1[(32'h0)+:(19)];
        delta$3 = g0$kdy$1[(32'h0)+:(19)];
        delta$5 = g1$kdx$1[(32'h0)+:(19)];
        delta$7 = g1$kdy$1[(32'h0)+:(19)];
        delta$9 = g2$kdx$1[(32'h0)+:(19)];
        delta$11 = g2$kdy$1[(32'h0)+:(19)];
        delta$13 = g3$kdx$1[(32'h0)+:(19)];
        delta$15 = g3$kdy$1[(32'h0)+:(19)];
        delta$17 = g4$kdx$1[(32'h0)+:(19)];
        delta$19 = g4$kdy$1[(32'h0)+:(19)];
        delta$21 = g5$kdx$1[(32'h0)+:(19)];
        delta$23 = g5$kdy$1[(32'h0)+:(19)];
        eq_b$0 = delta$0;
        if (maj_left$0) begin
            eq_b$0 = ((32'h0) & 19'h7ffff) - delta$0;
        end
        eq_b$1 = delta$1;
        if (maj_left$0) begin
            eq_b$1 = ((32'h0) & 19'h7ffff) - delta$1;
        end
        eq_b$2 = delta$2;
        if (maj_left$0) begin
            eq_b$2 = ((32'h0) & 19'h7ffff) - delta$2;
        end
        eq_b$3 = delta$3;
        if (maj_left$0) begin
            eq_b$3 = ((32'h0) & 19'h7ffff) - delta$3;
        end
        eq_b$4 = delta$4;
        if (maj_left$1) begin
            eq_b$4 = ((32'h0) & 19'h7ffff) - delta$4;
        end
        eq_b$5 = delta$5;
        if (maj_left$1) begin
            eq_b$5 = ((32'h0) & 19'h7ffff) - delta$5;
        end
        eq_b$6 = delta$6;
        if (maj_left$1) begin
            eq_b$6 = ((32'h0) & 19'h7ffff) - delta$6;
        end
        eq_b$7 = delta$7;
        if (maj_left$1) begin
            eq_b$7 = ((32'h0) & 19'h7ffff) - delta$7;
        end
        eq_b$8 = delta$8;
        if (maj_left$2) begin
            eq_b$8 = ((32'h0) & 19'h7ffff) - delta$8;
        end
        eq_b$9 = delta$9;
        if (maj_left$2) begin
            eq_b$9 = ((32'h0) & 19'h7ffff) - delta$9;
        end
        eq_b$10 = delta$10;
        if (maj_left$2) begin
            eq_b$10 = ((32'h0) & 19'h7ffff) - delta$10;
        end
        eq_b$11 = delta$11;
        if (maj_left$2) begin
            eq_b$11 = ((32'h0) & 19'h7ffff) - delta$11;
        end
        eq_b$12 = delta$12;
        if (maj_left$3) begin
            eq_b$12 = ((32'h0) & 19'h7ffff) - delta$12;
        end
        eq_b$13 = delta$13;
        if (maj_left$3) begin
            eq_b$13 = ((32'h0) & 19'h7ffff) - delta$13;
        end
        eq_b$14 = delta$14;
        if (maj_left$3) begin
            eq_b$14 = ((32'h0) & 19'h7ffff) - delta$14;
        end
        eq_b$15 = delta$15;
        if (maj_left$3) begin
            eq_b$15 = ((32'h0) & 19'h7ffff) - delta$15;
        end
        eq_b$16 = delta$16;
        if (maj_left$4) begin
            eq_b$16 = ((32'h0) & 19'h7ffff) - delta$16;
        end
        eq_b$17 = delta$17;
        if (maj_left$4) begin
            eq_b$17 = ((32'h0) & 19'h7ffff) - delta$17;
        end
        eq_b$18 = delta$18;
        if (maj_left$4) begin
            eq_b$18 = ((32'h0) & 19'h7ffff) - delta$18;
        end
        eq_b$19 = delta$19;
        if (maj_left$4) begin
            eq_b$19 = ((32'h0) & 19'h7ffff) - delta$19;
        end
        eq_b$20 = delta$20;
        if (maj_left$5) begin
            eq_b$20 = ((32'h0) & 19'h7ffff) - delta$20;
        end
        eq_b$21 = delta$21;
        if (maj_left$5) begin
            eq_b$21 = ((32'h0) & 19'h7ffff) - delta$21;
        end
        eq_b$22 = delta$22;
        if (maj_left$5) begin
            eq_b$22 = ((32'h0) & 19'h7ffff) - delta$22;
        end
        eq_b$23 = delta$23;
        if (maj_left$5) begin
            eq_b$23 = ((32'h0) & 19'h7ffff) - delta$23;
        end
        op_e$0 = eq_b$0;
        op_e$1 = eq_b$1;
        op_e$2 = eq_b$2;
        op_e$3 = eq_b$3;
        op_g$0 = g0$dmaj$0;
        op_g$1 = g0$dbot$0;
        op_g$2 = g0$dbot$0;
        op_g$3 = g0$dmaj$0;
        op_g$4 = g0$dmaj$1;
        op_g$5 = g0$dbot$1;
        op_g$6 = g0$dbot$1;
        op_g$7 = g0$dmaj$1;
        op_g$8 = g0$dmaj$2;
        op_g$9 = g0$dbot$2;
        op_g$10 = g0$dbot$2;
        op_g$11 = g0$dmaj$2;
        op_g$12 = g0$dmaj$3;
        op_g$13 = g0$dbot$3;
        op_g$14 = g0$dbot$3;
        op_g$15 = g0$dmaj$3;
        op_s$0 = g0$off_x$0;
        op_s$1 = g0$off_y$0;
        op_s$2 = g0$off_x$0;
        op_s$3 = g0$off_y$0;
        op_s$4 = g0$off_x$0;
        op_s$5 = g0$off_y$0;
        op_s$6 = g0$off_x$0;
        op_s$7 = g0$off_y$0;
        op_s$8 = g0$off_x$1;
        op_s$9 = g0$off_y$1;
        op_s$10 = g0$off_x$1;
        op_s$11 = g0$off_y$1;
        op_s$12 = g0$off_x$1;
        op_s$13 = g0$off_y$1;
        op_s$14 = g0$off_x$1;
        op_s$15 = g0$off_y$1;
        op_s$16 = g0$off_x$2;
        op_s$17 = g0$off_y$2;
        op_s$18 = g0$off_x$2;
        op_s$19 = g0$off_y$2;
        op_s$20 = g0$off_x$2;
        op_s$21 = g0$off_y$2;
        op_s$22 = g0$off_x$2;
        op_s$23 = g0$off_y$2;
        if (view$8 == 32'h1) begin
            op_e$0 = eq_b$4;
        end
        if (view$9 == 32'h1) begin
            op_e$1 = eq_b$5;
        end
        if (view$10 == 32'h1) begin
            op_e$2 = eq_b$6;
        end
        if (view$11 == 32'h1) begin
            op_e$3 = eq_b$7;
        end
        if (view$12 == 32'h1) begin
            op_g$0 = g1$dmaj$0;
        end
        if (view$13 == 32'h1) begin
            op_g$1 = g1$dbot$0;
        end
        if (view$14 == 32'h1) begin
            op_g$2 = g1$dbot$0;
        end
        if (view$15 == 32'h1) begin
            op_g$3 = g1$dmaj$0;
        end
        if (view$16 == 32'h1) begin
            op_g$4 = g1$dmaj$1;
        end
        if (view$17 == 32'h1) begin
            op_g$5 = g1$dbot$1;
        end
        if (view$18 == 32'h1) begin
            op_g$6 = g1$dbot$1;
        end
        if (view$19 == 32'h1) begin
            op_g$7 = g1$dmaj$1;
        end
        if (view$20 == 32'h1) begin
            op_g$8 = g1$dmaj$2;
        end
        if (view$21 == 32'h1) begin
            op_g$9 = g1$dbot$2;
        end
        if (view$22 == 32'h1) begin
            op_g$10 = g1$dbot$2;
        end
        if (view$23 == 32'h1) begin
            op_g$11 = g1$dmaj$2;
        end
        if (view$24 == 32'h1) begin
            op_g$12 = g1$dmaj$3;
        end
        if (view$25 == 32'h1) begin
            op_g$13 = g1$dbot$3;
        end
        if (view$26 == 32'h1) begin
            op_g$14 = g1$dbot$3;
        end
        if (view$27 == 32'h1) begin
            op_g$15 = g1$dmaj$3;
        end
        if (view$28 == 32'h1) begin
            op_s$0 = g1$off_x$0;
        end
        if (view$29 == 32'h1) begin
            op_s$1 = g1$off_y$0;
        end
        if (view$31 == 32'h1) begin
            op_s$2 = g1$off_x$0;
        end
        if (view$32 == 32'h1) begin
            op_s$3 = g1$off_y$0;
        end
        if (view$34 == 32'h1) begin
            op_s$4 = g1$off_x$0;
        end
        if (view$35 == 32'h1) begin
            op_s$5 = g1$off_y$0;
        end
        if (view$37 == 32'h1) begin
            op_s$6 = g1$off_x$0;
        end
        if (view$38 == 32'h1) begin
            op_s$7 = g1$off_y$0;
        end
        if (view$40 == 32'h1) begin
            op_s$8 = g1$off_x$1;
        end
        if (view$41 == 32'h1) begin
            op_s$9 = g1$off_y$1;
        end
        if (view$43 == 32'h1) begin
            op_s$10 = g1$off_x$1;
        end
        if (view$44 == 32'h1) begin
            op_s$11 = g1$off_y$1;
        end
        if (view$46 == 32'h1) begin
            op_s$12 = g1$off_x$1;
        end
        if (view$47 == 32'h1) begin
            op_s$13 = g1$off_y$1;
        end
        if (view$49 == 32'h1) begin
            op_s$14 = g1$off_x$1;
        end
        if (view$50 == 32'h1) begin
            op_s$15 = g1$off_y$1;
        end
        if (view$52 == 32'h1) begin
            op_s$16 = g1$off_x$2;
        end
        if (view$53 == 32'h1) begin
            op_s$17 = g1$off_y$2;
        end
        if (view$55 == 32'h1) begin
            op_s$18 = g1$off_x$2;
        end
        if (view$56 == 32'h1) begin
            op_s$19 = g1$off_y$2;
        end
        if (view$58 == 32'h1) begin
            op_s$20 = g1$off_x$2;
        end
        if (view$59 == 32'h1) begin
            op_s$21 = g1$off_y$2;
        end
        if (view$61 == 32'h1) begin
            op_s$22 = g1$off_x$2;
        end
        if (view$62 == 32'h1) begin
            op_s$23 = g1$off_y$2;
        end
        if (view$8 == 32'h2) begin
            op_e$0 = eq_b$8;
        end
        if (view$9 == 32'h2) begin
            op_e$1 = eq_b$9;
        end
        if (view$10 == 32'h2) begin
            op_e$2 = eq_b$10;
        end
        if (view$11 == 32'h2) begin
            op_e$3 = eq_b$11;
        end
        if (view$12 == 32'h2) begin
            op_g$0 = g2$dmaj$0;
        end
        if (view$13 == 32'h2) begin
            op_g$1 = g2$dbot$0;
        end
        if (view$14 == 32'h2) begin
            op_g$2 = g2$dbot$0;
        end
        if (view$15 == 32'h2) begin
            op_g$3 = g2$dmaj$0;
        end
        if (view$16 == 32'h2) begin
            op_g$4 = g2$dmaj$1;
        end
        if (view$17 == 32'h2) begin
            op_g$5 = g2$dbot$1;
        end
        if (view$18 == 32'h2) begin
            op_g$6 = g2$dbot$1;
        end
        if (view$19 == 32'h2) begin
            op_g$7 = g2$dmaj$1;
        end
        if (view$20 == 32'h2) begin
            op_g$8 = g2$dmaj$2;
        end
        if (view$21 == 32'h2) begin
            op_g$9 = g2$dbot$2;
        end
        if (view$22 == 32'h2) begin
            op_g$10 = g2$dbot$2;
        end
        if (view$23 == 32'h2) begin
            op_g$11 = g2$dmaj$2;
        end
        if (view$24 == 32'h2) begin
            op_g$12 = g2$dmaj$3;
        end
        if (view$25 == 32'h2) begin
            op_g$13 = g2$dbot$3;
        end
        if (view$26 == 32'h2) begin
            op_g$14 = g2$dbot$3;
        end
        if (view$27 == 32'h2) begin
            op_g$15 = g2$dmaj$3;
        end
        if (view$28 == 32'h2) begin
            op_s$0 = g2$off_x$0;
        end
        if (view$29 == 32'h2) begin
            op_s$1 = g2$off_y$0;
        end
        if (view$31 == 32'h2) begin
            op_s$2 = g2$off_x$0;
        end
        if (view$32 == 32'h2) begin
            op_s$3 = g2$off_y$0;
        end
        if (view$34 == 32'h2) begin
            op_s$4 = g2$off_x$0;
        end
        if (view$35 == 32'h2) begin
            op_s$5 = g2$off_y$0;
        end
        if (view$37 == 32'h2) begin
            op_s$6 = g2$off_x$0;
        end
        if (view$38 == 32'h2) begin
            op_s$7 = g2$off_y$0;
        end
        if (view$40 == 32'h2) begin
            op_s$8 = g2$off_x$1;
        end
        if (view$41 == 32'h2) begin
            op_s$9 = g2$off_y$1;
        end
        if (view$43 == 32'h2) begin
            op_s$10 = g2$off_x$1;
        end
        if (view$44 == 32'h2) begin
            op_s$11 = g2$off_y$1;
        end
        if (view$46 == 32'h2) begin
            op_s$12 = g2$off_x$1;
        end
        if (view$47 == 32'h2) begin
            op_s$13 = g2$off_y$1;
        end
        if (view$49 == 32'h2) begin
            op_s$14 = g2$off_x$1;
        end
        if (view$50 == 32'h2) begin
            op_s$15 = g2$off_y$1;
        end
        if (view$52 == 32'h2) begin
            op_s$16 = g2$off_x$2;
        end
        if (view$53 == 32'h2) begin
            op_s$17 = g2$off_y$2;
        end
        if (view$55 == 32'h2) begin
            op_s$18 = g2$off_x$2;
        end
        if (view$56 == 32'h2) begin
            op_s$19 = g2$off_y$2;
        end
        if (view$58 == 32'h2) begin
            op_s$20 = g2$off_x$2;
        end
        if (view$59 == 32'h2) begin
            op_s$21 = g2$off_y$2;
        end
        if (view$61 == 32'h2) begin
            op_s$22 = g2$off_x$2;
        end
        if (view$62 == 32'h2) begin
            op_s$23 = g2$off_y$2;
        end
        if (view$8 == 32'h3) begin
            op_e$0 = eq_b$12;
        end
        if (view$9 == 32'h3) begin
            op_e$1 = eq_b$13;
        end
        if (view$10 == 32'h3) begin
            op_e$2 = eq_b$14;
        end
        if (view$11 == 32'h3) begin
            op_e$3 = eq_b$15;
        end
        if (view$12 == 32'h3) begin
            op_g$0 = g3$dmaj$0;
        end
        if (view$13 == 32'h3) begin
            op_g$1 = g3$dbot$0;
        end
        if (view$14 == 32'h3) begin
            op_g$2 = g3$dbot$0;
        end
        if (view$15 == 32'h3) begin
            op_g$3 = g3$dmaj$0;
        end
        if (view$16 == 32'h3) begin
            op_g$4 = g3$dmaj$1;
        end
        if (view$17 == 32'h3) begin
            op_g$5 = g3$dbot$1;
        end
        if (view$18 == 32'h3) begin
            op_g$6 = g3$dbot$1;
        end
        if (view$19 == 32'h3) begin
            op_g$7 = g3$dmaj$1;
        end
        if (view$20 == 32'h3) begin
            op_g$8 = g3$dmaj$2;
        end
        if (view$21 == 32'h3) begin
            op_g$9 = g3$dbot$2;
        end
        if (view$22 == 32'h3) begin
            op_g$10 = g3$dbot$2;
        end
        if (view$23 == 32'h3) begin
            op_g$11 = g3$dmaj$2;
        end
        if (view$24 == 32'h3) begin
            op_g$12 = g3$dmaj$3;
        end
        if (view$25 == 32'h3) begin
            op_g$13 = g3$dbot$3;
        end
        if (view$26 == 32'h3) begin
            op_g$14 = g3$dbot$3;
        end
        if (view$27 == 32'h3) begin
            op_g$15 = g3$dmaj$3;
        end
        if (view$28 == 32'h3) begin
            op_s$0 = g3$off_x$0;
        end
        if (view$29 == 32'h3) begin
            op_s$1 = g3$off_y$0;
        end
        if (view$31 == 32'h3) begin
            op_s$2 = g3$off_x$0;
        end
        if (view$32 == 32'h3) begin
            op_s$3 = g3$off_y$0;
        end
        if (view$34 == 32'h3) begin
            op_s$4 = g3$off_x$0;
        end
        if (view$35 == 32'h3) begin
            op_s$5 = g3$off_y$0;
        end
        if (view$37 == 32'h3) begin
            op_s$6 = g3$off_x$0;
        end
        if (view$38 == 32'h3) begin
            op_s$7 = g3$off_y$0;
        end
        if (view$40 == 32'h3) begin
            op_s$8 = g3$off_x$1;
        end
        if (view$41 == 32'h3) begin
            op_s$9 = g3$off_y$1;
        end
        if (view$43 == 32'h3) begin
            op_s$10 = g3$off_x$1;
        end
        if (view$44 == 32'h3) begin
            op_s$11 = g3$off_y$1;
        end
        if (view$46 == 32'h3) begin
            op_s$12 = g3$off_x$1;
        end
        if (view$47 == 32'h3) begin
            op_s$13 = g3$off_y$1;
        end
        if (view$49 == 32'h3) begin
            op_s$14 = g3$off_x$1;
        end
        if (view$50 == 32'h3) begin
            op_s$15 = g3$off_y$1;
        end
        if (view$52 == 32'h3) begin
            op_s$16 = g3$off_x$2;
        end
        if (view$53 == 32'h3) begin
            op_s$17 = g3$off_y$2;
        end
        if (view$55 == 32'h3) begin
            op_s$18 = g3$off_x$2;
        end
        if (view$56 == 32'h3) begin
            op_s$19 = g3$off_y$2;
        end
        if (view$58 == 32'h3) begin
            op_s$20 = g3$off_x$2;
        end
        if (view$59 == 32'h3) begin
            op_s$21 = g3$off_y$2;
        end
        if (view$61 == 32'h3) begin
            op_s$22 = g3$off_x$2;
        end
        if (view$62 == 32'h3) begin
            op_s$23 = g3$off_y$2;
        end
        if (view$8 == 32'h4) begin
            op_e$0 = eq_b$16;
        end
        if (view$9 == 32'h4) begin
            op_e$1 = eq_b$17;
        end
        if (view$10 == 32'h4) begin
            op_e$2 = eq_b$18;
        end
        if (view$11 == 32'h4) begin
            op_e$3 = eq_b$19;
        end
        if (view$12 == 32'h4) begin
            op_g$0 = g4$dmaj$0;
        end
        if (view$13 == 32'h4) begin
            op_g$1 = g4$dbot$0;
        end
        if (view$14 == 32'h4) begin
            op_g$2 = g4$dbot$0;
        end
        if (view$15 == 32'h4) begin
            op_g$3 = g4$dmaj$0;
        end
        if (view$16 == 32'h4) begin
            op_g$4 = g4$dmaj$1;
        end
        if (view$17 == 32'h4) begin
            op_g$5 = g4$dbot$1;
        end
        if (view$18 == 32'h4) begin
            op_g$6 = g4$dbot$1;
        end
        if (view$19 == 32'h4) begin
            op_g$7 = g4$dmaj$1;
        end
        if (view$20 == 32'h4) begin
            op_g$8 = g4$dmaj$2;
        end
        if (view$21 == 32'h4) begin
            op_g$9 = g4$dbot$2;
        end
        if (view$22 == 32'h4) begin
            op_g$10 = g4$dbot$2;
        end
        if (view$23 == 32'h4) begin
            op_g$11 = g4$dmaj$2;
        end
        if (view$24 == 32'h4) begin
            op_g$12 = g4$dmaj$3;
        end
        if (view$25 == 32'h4) begin
            op_g$13 = g4$dbot$3;
        end
        if (view$26 == 32'h4) begin
            op_g$14 = g4$dbot$3;
        end
        if (view$27 == 32'h4) begin
            op_g$15 = g4$dmaj$3;
        end
        if (view$28 == 32'h4) begin
            op_s$0 = g4$off_x$0;
        end
        if (view$29 == 32'h4) begin
            op_s$1 = g4$off_y$0;
        end
        if (view$31 == 32'h4) begin
            op_s$2 = g4$off_x$0;
        end
        if (view$32 == 32'h4) begin
            op_s$3 = g4$off_y$0;
        end
        if (view$34 == 32'h4) begin
            op_s$4 = g4$off_x$0;
        end
        if (view$35 == 32'h4) begin
            op_s$5 = g4$off_y$0;
        end
        if (view$37 == 32'h4) begin
            op_s$6 = g4$off_x$0;
        end
        if (view$38 == 32'h4) begin
            op_s$7 = g4$off_y$0;
        end
        if (view$40 == 32'h4) begin
            op_s$8 = g4$off_x$1;
        end
        if (view$41 == 32'h4) begin
            op_s$9 = g4$off_y$1;
        end
        if (view$43 == 32'h4) begin
            op_s$10 = g4$off_x$1;
        end
        if (view$44 == 32'h4) begin
            op_s$11 = g4$off_y$1;
        end
        if (view$46 == 32'h4) begin
            op_s$12 = g4$off_x$1;
        end
        if (view$47 == 32'h4) begin
            op_s$13 = g4$off_y$1;
        end
        if (view$49 == 32'h4) begin
            op_s$14 = g4$off_x$1;
        end
        if (view$50 == 32'h4) begin
            op_s$15 = g4$off_y$1;
        end
        if (view$52 == 32'h4) begin
            op_s$16 = g4$off_x$2;
        end
        if (view$53 == 32'h4) begin
            op_s$17 = g4$off_y$2;
        end
        if (view$55 == 32'h4) begin
            op_s$18 = g4$off_x$2;
        end
        if (view$56 == 32'h4) begin
            op_s$19 = g4$off_y$2;
        end
        if (view$58 == 32'h4) begin
            op_s$20 = g4$off_x$2;
        end
        if (view$59 == 32'h4) begin
            op_s$21 = g4$off_y$2;
        end
        if (view$61 == 32'h4) begin
            op_s$22 = g4$off_x$2;
        end
        if (view$62 == 32'h4) begin
            op_s$23 = g4$off_y$2;
        end
        if (view$8 == 32'h5) begin
            op_e$0 = eq_b$20;
        end
        if (view$9 == 32'h5) begin
            op_e$1 = eq_b$21;
        end
        if (view$10 == 32'h5) begin
            op_e$2 = eq_b$22;
        end
        if (view$11 == 32'h5) begin
            op_e$3 = eq_b$23;
        end
        if (view$12 == 32'h5) begin
            op_g$0 = g5$dmaj$0;
        end
        if (view$13 == 32'h5) begin
            op_g$1 = g5$dbot$0;
        end
        if (view$14 == 32'h5) begin
            op_g$2 = g5$dbot$0;
        end
        if (view$15 == 32'h5) begin
            op_g$3 = g5$dmaj$0;
        end
        if (view$16 == 32'h5) begin
            op_g$4 = g5$dmaj$1;
        end
        if (view$17 == 32'h5) begin
            op_g$5 = g5$dbot$1;
        end
        if (view$18 == 32'h5) begin
            op_g$6 = g5$dbot$1;
        end
        if (view$19 == 32'h5) begin
            op_g$7 = g5$dmaj$1;
        end
        if (view$20 == 32'h5) begin
            op_g$8 = g5$dmaj$2;
        end
        if (view$21 == 32'h5) begin
            op_g$9 = g5$dbot$2;
        end
        if (view$22 == 32'h5) begin
            op_g$10 = g5$dbot$2;
        end
        if (view$23 == 32'h5) begin
            op_g$11 = g5$dmaj$2;
        end
        if (view$24 == 32'h5) begin
            op_g$12 = g5$dmaj$3;
        end
        if (view$25 == 32'h5) begin
            op_g$13 = g5$dbot$3;
        end
        if (view$26 == 32'h5) begin
            op_g$14 = g5$dbot$3;
        end
        if (view$27 == 32'h5) begin
            op_g$15 = g5$dmaj$3;
        end
        if (view$28 == 32'h5) begin
            op_s$0 = g5$off_x$0;
        end
        if (view$29 == 32'h5) begin
            op_s$1 = g5$off_y$0;
        end
        if (view$31 == 32'h5) begin
            op_s$2 = g5$off_x$0;
        end
        if (view$32 == 32'h5) begin
            op_s$3 = g5$off_y$0;
        end
        if (view$34 == 32'h5) begin
            op_s$4 = g5$off_x$0;
        end
        if (view$35 == 32'h5) begin
            op_s$5 = g5$off_y$0;
        end
        if (view$37 == 32'h5) begin
            op_s$6 = g5$off_x$0;
        end
        if (view$38 == 32'h5) begin
            op_s$7 = g5$off_y$0;
        end
        if (view$40 == 32'h5) begin
            op_s$8 = g5$off_x$1;
        end
        if (view$41 == 32'h5) begin
            op_s$9 = g5$off_y$1;
        end
        if (view$43 == 32'h5) begin
            op_s$10 = g5$off_x$1;
        end
        if (view$44 == 32'h5) begin
            op_s$11 = g5$off_y$1;
        end
        if (view$46 == 32'h5) begin
            op_s$12 = g5$off_x$1;
        end
        if (view$47 == 32'h5) begin
            op_s$13 = g5$off_y$1;
        end
        if (view$49 == 32'h5) begin
            op_s$14 = g5$off_x$1;
        end
        if (view$50 == 32'h5) begin
            op_s$15 = g5$off_y$1;
        end
        if (view$52 == 32'h5) begin
            op_s$16 = g5$off_x$2;
        end
        if (view$53 == 32'h5) begin
            op_s$17 = g5$off_y$2;
        end
        if (view$55 == 32'h5) begin
            op_s$18 = g5$off_x$2;
        end
        if (view$56 == 32'h5) begin
            op_s$19 = g5$off_y$2;
        end
        if (view$58 == 32'h5) begin
            op_s$20 = g5$off_x$2;
        end
        if (view$59 == 32'h5) begin
            op_s$21 = g5$off_y$2;
        end
        if (view$61 == 32'h5) begin
            op_s$22 = g5$off_x$2;
        end
        if (view$62 == 32'h5) begin
            op_s$23 = g5$off_y$2;
        end
        ddx$0 = gx$0$q >> gsh$0;
        ddy$0 = gy$0$q >> gsh$0;
        ddx$1 = gx$1$q >> gsh$1;
        ddy$1 = gy$1$q >> gsh$1;
        ddx$2 = gx$2$q >> gsh$2;
        ddy$2 = gy$2$q >> gsh$2;
        ddx$3 = gx$3$q >> gsh$3;
        ddy$3 = gy$3$q >> gsh$3;
        attr0$0 = g0$attr0$0;
        if (view_handover == 32'h1) begin
            attr0$0 = g1$attr0$0;
        end
        if (view_handover == 32'h2) begin
            attr0$0 = g2$attr0$0;
        end
        if (view_handover == 32'h3) begin
            attr0$0 = g3$attr0$0;
        end
        if (view_handover == 32'h4) begin
            attr0$0 = g4$attr0$0;
        end
        if (view_handover == 32'h5) begin
            attr0$0 = g5$attr0$0;
        end
        attr0$1 = g0$attr0$1;
        if (view_handover == 32'h1) begin
            attr0$1 = g1$attr0$1;
        end
        if (view_handover == 32'h2) begin
            attr0$1 = g2$attr0$1;
        end
        if (view_handover == 32'h3) begin
            attr0$1 = g3$attr0$1;
        end
        if (view_handover == 32'h4) begin
            attr0$1 = g4$attr0$1;
        end
        if (view_handover == 32'h5) begin
            attr0$1 = g5$attr0$1;
        end
        attr0$2 = g0$attr0$2;
        if (view_handover == 32'h1) begin
            attr0$2 = g1$attr0$2;
        end
        if (view_handover == 32'h2) begin
            attr0$2 = g2$attr0$2;
        end
        if (view_handover == 32'h3) begin
            attr0$2 = g3$attr0$2;
        end
        if (view_handover == 32'h4) begin
            attr0$2 = g4$attr0$2;
        end
        if (view_handover == 32'h5) begin
            attr0$2 = g5$attr0$2;
        end
        attr0$3 = g0$attr0$3;
        if (view_handover == 32'h1) begin
            attr0$3 = g1$attr0$3;
        end
        if (view_handover == 32'h2) begin
            attr0$3 = g2$attr0$3;
        end
        if (view_handover == 32'h3) begin
            attr0$3 = g3$attr0$3;
        end
        if (view_handover == 32'h4) begin
            attr0$3 = g4$attr0$3;
        end
        if (view_handover == 32'h5) begin
            attr0$3 = g5$attr0$3;
        end
        op_q$0 = q$0$q;
        if (view$30 == 1) begin
            op_q$0 = q$3$q;
        end
        if (view$30 == 2) begin
            op_q$0 = q$6$q;
        end
        if (view$30 == 3) begin
            op_q$0 = q$9$q;
        end
        if (view$30 == 4) begin
            op_q$0 = q$12$q;
        end
        if (view$30 == 5) begin
            op_q$0 = q$15$q;
        end
        op_q$1 = q$0$q;
        if (view$33 == 1) begin
            op_q$1 = q$3$q;
        end
        if (view$33 == 2) begin
            op_q$1 = q$6$q;
        end
        if (view$33 == 3) begin
            op_q$1 = q$9$q;
        end
        if (view$33 == 4) begin
            op_q$1 = q$12$q;
        end
        if (view$33 == 5) begin
            op_q$1 = q$15$q;
        end
        op_q$2 = q$0$q;
        if (view$36 == 1) begin
            op_q$2 = q$3$q;
        end
        if (view$36 == 2) begin
            op_q$2 = q$6$q;
        end
        if (view$36 == 3) begin
            op_q$2 = q$9$q;
        end
        if (view$36 == 4) begin
            op_q$2 = q$12$q;
        end
        if (view$36 == 5) begin
            op_q$2 = q$15$q;
        end
        op_q$3 = q$0$q;
        if (view$39 == 1) begin
            op_q$3 = q$3$q;
        end
        if (view$39 == 2) begin
            op_q$3 = q$6$q;
        end
        if (view$39 == 3) begin
            op_q$3 = q$9$q;
        end
        if (view$39 == 4) begin
            op_q$3 = q$12$q;
        end
        if (view$39 == 5) begin
            op_q$3 = q$15$q;
        end
        op_q$4 = q$1$q;
        if (view$42 == 1) begin
            op_q$4 = q$4$q;
        end
        if (view$42 == 2) begin
            op_q$4 = q$7$q;
        end
        if (view$42 == 3) begin
            op_q$4 = q$10$q;
        end
        if (view$42 == 4) begin
            op_q$4 = q$13$q;
        end
        if (view$42 == 5) begin
            op_q$4 = q$16$q;
        end
        op_q$5 = q$1$q;
        if (view$45 == 1) begin
            op_q$5 = q$4$q;
        end
        if (view$45 == 2) begin
            op_q$5 = q$7$q;
        end
        if (view$45 == 3) begin
            op_q$5 = q$10$q;
        end
        if (view$45 == 4) begin
            op_q$5 = q$13$q;
        end
        if (view$45 == 5) begin
            op_q$5 = q$16$q;
        end
        op_q$6 = q$1$q;
        if (view$48 == 1) begin
            op_q$6 = q$4$q;
        end
        if (view$48 == 2) begin
            op_q$6 = q$7$q;
        end
        if (view$48 == 3) begin
            op_q$6 = q$10$q;
        end
        if (view$48 == 4) begin
            op_q$6 = q$13$q;
        end
        if (view$48 == 5) begin
            op_q$6 = q$16$q;
        end
        op_q$7 = q$1$q;
        if (view$51 == 1) begin
            op_q$7 = q$4$q;
        end
        if (view$51 == 2) begin
            op_q$7 = q$7$q;
        end
        if (view$51 == 3) begin
            op_q$7 = q$10$q;
        end
        if (view$51 == 4) begin
            op_q$7 = q$13$q;
        end
        if (view$51 == 5) begin
            op_q$7 = q$16$q;
        end
        op_q$8 = q$2$q;
        if (view$54 == 1) begin
            op_q$8 = q$5$q;
        end
        if (view$54 == 2) begin
            op_q$8 = q$8$q;
        end
        if (view$54 == 3) begin
            op_q$8 = q$11$q;
        end
        if (view$54 == 4) begin
            op_q$8 = q$14$q;
        end
        if (view$54 == 5) begin
            op_q$8 = q$17$q;
        end
        op_q$9 = q$2$q;
        if (view$57 == 1) begin
            op_q$9 = q$5$q;
        end
        if (view$57 == 2) begin
            op_q$9 = q$8$q;
        end
        if (view$57 == 3) begin
            op_q$9 = q$11$q;
        end
        if (view$57 == 4) begin
            op_q$9 = q$14$q;
        end
        if (view$57 == 5) begin
            op_q$9 = q$17$q;
        end
        op_q$10 = q$2$q;
        if (view$60 == 1) begin
            op_q$10 = q$5$q;
        end
        if (view$60 == 2) begin
            op_q$10 = q$8$q;
        end
        if (view$60 == 3) begin
            op_q$10 = q$11$q;
        end
        if (view$60 == 4) begin
            op_q$10 = q$14$q;
        end
        if (view$60 == 5) begin
            op_q$10 = q$17$q;
        end
        op_q$11 = q$2$q;
        if (view$63 == 1) begin
            op_q$11 = q$5$q;
        end
        if (view$63 == 2) begin
            op_q$11 = q$8$q;
        end
        if (view$63 == 3) begin
            op_q$11 = q$11$q;
        end
        if (view$63 == 4) begin
            op_q$11 = q$14$q;
        end
        if (view$63 == 5) begin
            op_q$11 = q$17$q;
        end
        mul$0$en = run;
        if ((lane$0 == 0) & act$0) begin
            mul$0$a = g0$kdx$0[(32'h0)+:(57)];
            mul$0$b = g0$kdy$1[(32'h0)+:(19)];
        end
        if ((lane$1 == 0) & act$1) begin
            mul$0$a = g0$kdx$1[(32'h0)+:(57)];
            mul$0$b = g0$kdy$0[(32'h0)+:(19)];
        end
        if ((lane$0 == 0) & add$0) begin
            pa$0 = mul$0$p[(32'h0)+:(34)];
        end
        if ((lane$1 == 0) & add$1) begin
            pa$1 = mul$0$p[(32'h0)+:(34)];
        end
        if ((lane$2 == 0) & act$2) begin
            mul$0$a = g0$edy$0;
            mul$0$b = g0$xf$0;
        end
        if ((lane$3 == 0) & act$3) begin
            mul$0$a = g0$edx$0[(32'h0)+:(57)];
            mul$0$b = g0$toff$0;
        end
        if ((lane$4 == 0) & act$4) begin
            mul$0$a = g0$edy$1;
            mul$0$b = g0$xf$1;
        end
        if ((lane$5 == 0) & act$5) begin
            mul$0$a = g0$edx$1[(32'h0)+:(57)];
            mul$0$b = g0$toff$1;
        end
        if ((lane$6 == 0) & act$6) begin
            mul$0$a = g0$edy$2;
            mul$0$b = g0$xf$2;
        end
        if ((lane$7 == 0) & act$7) begin
            mul$0$a = g0$edx$2[(32'h0)+:(57)];
            mul$0$b = g0$toff$2;
        end
        if ((lane$2 == 0) & add$2) begin
            pn$0 = mul$0$p;
        end
        if ((lane$3 == 0) & add$3) begin
            pn$1 = mul$0$p;
        end
        if ((lane$4 == 0) & add$4) begin
            pn$2 = mul$0$p;
        end
        if ((lane$5 == 0) & add$5) begin
            pn$3 = mul$0$p;
        end
        if ((lane$6 == 0) & add$6) begin
            pn$4 = mul$0$p;
        end
        if ((lane$7 == 0) & add$7) begin
            pn$5 = mul$0$p;
        end
        if ((lane$8 == 0) & act$8) begin
            mul$0$a = mant_s$q;
            mul$0$b = op_e$0;
        end
        if ((lane$8 == 0) & add$8) begin
            pe$0 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$9 == 0) & act$9) begin
            mul$0$a = mant_s$q;
            mul$0$b = op_e$1;
        end
        if ((lane$9 == 0) & add$9) begin
            pe$1 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$10 == 0) & act$10) begin
            mul$0$a = mant_s$q;
            mul$0$b = op_e$2;
        end
        if ((lane$10 == 0) & add$10) begin
            pe$2 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$11 == 0) & act$11) begin
            mul$0$a = mant_s$q;
            mul$0$b = op_e$3;
        end
        if ((lane$11 == 0) & add$11) begin
            pe$3 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$12 == 0) & act$12) begin
            mul$0$a = p$3$q;
            mul$0$b = op_g$0;
        end
        if ((lane$13 == 0) & act$13) begin
            mul$0$a = p$2$q;
            mul$0$b = op_g$1;
        end
        if ((lane$14 == 0) & act$14) begin
            mul$0$a = p$0$q;
            mul$0$b = op_g$2;
        end
        if ((lane$15 == 0) & act$15) begin
            mul$0$a = p$1$q;
            mul$0$b = op_g$3;
        end
        if ((lane$16 == 0) & act$16) begin
            mul$0$a = p$3$q;
            mul$0$b = op_g$4;
        end
        if ((lane$17 == 0) & act$17) begin
            mul$0$a = p$2$q;
            mul$0$b = op_g$5;
        end
        if ((lane$18 == 0) & act$18) begin
            mul$0$a = p$0$q;
            mul$0$b = op_g$6;
        end
        if ((lane$19 == 0) & act$19) begin
            mul$0$a = p$1$q;
            mul$0$b = op_g$7;
        end
        if ((lane$20 == 0) & act$20) begin
            mul$0$a = p$3$q;
            mul$0$b = op_g$8;
        end
        if ((lane$21 == 0) & act$21) begin
            mul$0$a = p$2$q;
            mul$0$b = op_g$9;
        end
        if ((lane$22 == 0) & act$22) begin
            mul$0$a = p$0$q;
            mul$0$b = op_g$10;
        end
        if ((lane$23 == 0) & act$23) begin
            mul$0$a = p$1$q;
            mul$0$b = op_g$11;
        end
        if ((lane$24 == 0) & act$24) begin
            mul$0$a = p$3$q;
            mul$0$b = op_g$12;
        end
        if ((lane$25 == 0) & act$25) begin
            mul$0$a = p$2$q;
            mul$0$b = op_g$13;
        end
        if ((lane$26 == 0) & act$26) begin
            mul$0$a = p$0$q;
            mul$0$b = op_g$14;
        end
        if ((lane$27 == 0) & act$27) begin
            mul$0$a = p$1$q;
            mul$0$b = op_g$15;
        end
        if ((lane$12 == 0) & add$12) begin
            pg$0 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$13 == 0) & add$13) begin
            pg$1 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$14 == 0) & add$14) begin
            pg$2 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$15 == 0) & add$15) begin
            pg$3 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$16 == 0) & add$16) begin
            pg$4 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$17 == 0) & add$17) begin
            pg$5 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$18 == 0) & add$18) begin
            pg$6 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$19 == 0) & add$19) begin
            pg$7 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$20 == 0) & add$20) begin
            pg$8 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$21 == 0) & add$21) begin
            pg$9 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$22 == 0) & add$22) begin
            pg$10 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$23 == 0) & add$23) begin
            pg$11 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$24 == 0) & add$24) begin
            pg$12 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$25 == 0) & add$25) begin
            pg$13 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$26 == 0) & add$26) begin
            pg$14 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$27 == 0) & add$27) begin
            pg$15 = mul$0$p[(32'h0)+:(57)];
        end
        if ((lane$28 == 0) & act$28) begin
            mul$0$a = ddx$0;
            mul$0$b = op_s$0;
        end
        if ((lane$29 == 0) & act$29) begin
            mul$0$a = ddy$0;
            mul$0$b = op_s$1;
        end
        if ((lane$30 == 0) & act$30) begin
            mul$0$a = ddx$0;
            mul$0$b = op_q$0;
        end
        if ((lane$31 == 0) & act$31) begin
            mul$0$a = ddx$1;
            mul$0$b = op_s$2;
        end
        if ((lane$32 == 0) & act$32) begin
            mul$0$a = ddy$1;
            mul$0$b = op_s$3;
        end
        if ((lane$33 == 0) & act$33) begin
            mul$0$a = ddx$1;
            mul$0$b = op_q$1;
        end
        if ((lane$34 == 0) & act$34) begin
            mul$0$a = ddx$2;
            mul$0$b = op_s$4;
        end
        if ((lane$35 == 0) & act$35) begin
            mul$0$a = ddy$2;
            mul$0$b = op_s$5;
        end
        if ((lane$36 == 0) & act$36) begin
            mul$0$a = ddx$2;
            mul$0$b = op_q$2;
        end
        if ((lane$37 == 0) & act$37) begin
            mul$0$a = ddx$3;
            mul$0$b = op_s$6;
        end
        if ((lane$38 == 0) & act$38) begin
            mul$0$a = ddy$3;
            mul$0$b = op_s$7;
        end
        if ((lane$39 == 0) & act$39) begin
            mul$0$a = ddx$3;
            mul$0$b = op_q$3;
        end
        if ((lane$40 == 0) & act$40) begin
            mul$0$a = ddx$0;
            mul$0$b = op_s$8;
        end
        if ((lane$41 == 0) & act$41) begin
            mul$0$a = ddy$0;
            mul$0$b = op_s$9;
        end
        if ((lane$42 == 0) & act$42) begin
            mul$0$a = ddx$0;
            mul$0$b = op_q$4;
        end
        if ((lane$43 == 0) & act$43) begin
            mul$0$a = ddx$1;
            mul$0$b = op_s$10;
        end
        if ((lane$44 == 0) & act$44) begin
            mul$0$a = ddy$1;
            mul$0$b = op_s$11;
        end
        if ((lane$45 == 0) & act$45) begin
            mul$0$a = ddx$1;
            mul$0$b = op_q$5;
        end
        if ((lane$46 == 0) & act$46) begin
            mul$0$a = ddx$2;
            mul$0$b = op_s$12;
        end
        if ((lane$47 == 0) & act$47) begin
            mul$0$a = ddy$2;
            mul$0$b = op_s$13;
        end
        if ((lane$48 == 0) & act$48) begin
            mul$0$a = ddx$2;
            mul$0$b = op_q$6;
        end
        if ((lane$49 == 0) & act$49) begin
            mul$0$a = ddx$3;
            mul$0$b = op_s$14;
        end
        if ((lane$50 == 0) & act$50) begin
            mul$0$a = ddy$3;
            mul$0$b = op_s$15;
        end
        if ((lane$51 == 0) & act$51) begin
            mul$0$a = ddx$3;
            mul$0$b = op_q$7;
        end
        if ((lane$52 == 0) & act$52) begin
            mul$0$a = ddx$0;
            mul$0$b = op_s$16;
        end
        if ((lane$53 == 0) & act$53) begin
            mul$0$a = ddy$0;
            mul$0$b = op_s$17;
        end
        if ((lane$54 == 0) & act$54) begin
            mul$0$a = ddx$0;
            mul$0$b = op_q$8;
        end
        if ((lane$55 == 0) & act$55) begin
            mul$0$a = ddx$1;
            mul$0$b = op_s$18;
        end
        if ((lane$56 == 0) & act$56) begin
            mul$0$a = ddy$1;
            mul$0$b = op_s$19;
        end
        if ((lane$57 == 0) & act$57) begin
            mul$0$a = ddx$1;
            mul$0$b = op_q$9;
        end
        if ((lane$58 == 0) & act$58) begin
            mul$0$a = ddx$2;
            mul$0$b = op_s$20;
        end
        if ((lane$59 == 0) & act$59) begin
            mul$0$a = ddy$2;
            mul$0$b = op_s$21;
        end
        if ((lane$60 == 0) & act$60) begin
            mul$0$a = ddx$2;
            mul$0$b = op_q$10;
        end
        if ((lane$61 == 0) & act$61) begin
            mul$0$a = ddx$3;
            mul$0$b = op_s$22;
        end
        if ((lane$62 == 0) & act$62) begin
            mul$0$a = ddy$3;
            mul$0$b = op_s$23;
        end
        if ((lane$63 == 0) & act$63) begin
            mul$0$a = ddx$3;
            mul$0$b = op_q$11;
        end
        if ((lane$28 == 0) & add$28) begin
            ps$0 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$29 == 0) & add$29) begin
            ps$1 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$30 == 0) & add$30) begin
            ps$2 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$31 == 0) & add$31) begin
            ps$3 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$32 == 0) & add$32) begin
            ps$4 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$33 == 0) & add$33) begin
            ps$5 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$34 == 0) & add$34) begin
            ps$6 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$35 == 0) & add$35) begin
            ps$7 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$36 == 0) & add$36) begin
            ps$8 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$37 == 0) & add$37) begin
            ps$9 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$38 == 0) & add$38) begin
            ps$10 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$39 == 0) & add$39) begin
            ps$11 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$40 == 0) & add$40) begin
            ps$12 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$41 == 0) & add$41) begin
            ps$13 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$42 == 0) & add$42) begin
            ps$14 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$43 == 0) & add$43) begin
            ps$15 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$44 == 0) & add$44) begin
            ps$16 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$45 == 0) & add$45) begin
            ps$17 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$46 == 0) & add$46) begin
            ps$18 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$47 == 0) & add$47) begin
            ps$19 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$48 == 0) & add$48) begin
            ps$20 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$49 == 0) & add$49) begin
            ps$21 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$50 == 0) & add$50) begin
            ps$22 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$51 == 0) & add$51) begin
            ps$23 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$52 == 0) & add$52) begin
            ps$24 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$53 == 0) & add$53) begin
            ps$25 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$54 == 0) & add$54) begin
            ps$26 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$55 == 0) & add$55) begin
            ps$27 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$56 == 0) & add$56) begin
            ps$28 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$57 == 0) & add$57) begin
            ps$29 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$58 == 0) & add$58) begin
            ps$30 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$59 == 0) & add$59) begin
            ps$31 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$60 == 0) & add$60) begin
            ps$32 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$61 == 0) & add$61) begin
            ps$33 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$62 == 0) & add$62) begin
            ps$34 = mul$0$p[(32'h0)+:(40)];
        end
        if ((lane$63 == 0) & add$63) begin
            ps$35 = mul$0$p[(32'h0)+:(40)];
        end
        mul$1$en = run;
        if ((lane$0 == 1) & act$0) begin
            mul$1$a = g0$kdx$0[(32'h0)+:(57)];
            mul$1$b = g0$kdy$1[(32'h0)+:(19)];
        end
        if ((lane$1 == 1) & act$1) begin
            mul$1$a = g0$kdx$1[(32'h0)+:(57)];
            mul$1$b = g0$kdy$0[(32'h0)+:(19)];
        end
        if ((lane$0 == 1) & add$0) begin
            pa$0 = mul$1$p[(32'h0)+:(34)];
        end
        if ((lane$1 == 1) & add$1) begin
            pa$1 = mul$1$p[(32'h0)+:(34)];
        end
        if ((lane$2 == 1) & act$2) begin
            mul$1$a = g0$edy$0;
            mul$1$b = g0$xf$0;
        end
        if ((lane$3 == 1) & act$3) begin
            mul$1$a = g0$edx$0[(32'h0)+:(57)];
            mul$1$b = g0$toff$0;
        end
        if ((lane$4 == 1) & act$4) begin
            mul$1$a = g0$edy$1;
            mul$1$b = g0$xf$1;
        end
        if ((lane$5 == 1) & act$5) begin
            mul$1$a = g0$edx$1[(32'h0)+:(57)];
            mul$1$b = g0$toff$1;
        end
        if ((lane$6 == 1) & act$6) begin
            mul$1$a = g0$edy$2;
            mul$1$b = g0$xf$2;
        end
        if ((lane$7 == 1) & act$7) begin
            mul$1$a = g0$edx$2[(32'h0)+:(57)];
            mul$1$b = g0$toff$2;
        end
        if ((lane$2 == 1) & add$2) begin
            pn$0 = mul$1$p;
        end
        if ((lane$3 == 1) & add$3) begin
            pn$1 = mul$1$p;
        end
        if ((lane$4 == 1) & add$4) begin
            pn$2 = mul$1$p;
        end
        if ((lane$5 == 1) & add$5) begin
            pn$3 = mul$1$p;
        end
        if ((lane$6 == 1) & add$6) begin
            pn$4 = mul$1$p;
        end
        if ((lane$7 == 1) & add$7) begin
            pn$5 = mul$1$p;
        end
        if ((lane$8 == 1) & act$8) begin
            mul$1$a = mant_s$q;
            mul$1$b = op_e$0;
        end
        if ((lane$8 == 1) & add$8) begin
            pe$0 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$9 == 1) & act$9) begin
            mul$1$a = mant_s$q;
            mul$1$b = op_e$1;
        end
        if ((lane$9 == 1) & add$9) begin
            pe$1 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$10 == 1) & act$10) begin
            mul$1$a = mant_s$q;
            mul$1$b = op_e$2;
        end
        if ((lane$10 == 1) & add$10) begin
            pe$2 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$11 == 1) & act$11) begin
            mul$1$a = mant_s$q;
            mul$1$b = op_e$3;
        end
        if ((lane$11 == 1) & add$11) begin
            pe$3 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$12 == 1) & act$12) begin
            mul$1$a = p$3$q;
            mul$1$b = op_g$0;
        end
        if ((lane$13 == 1) & act$13) begin
            mul$1$a = p$2$q;
            mul$1$b = op_g$1;
        end
        if ((lane$14 == 1) & act$14) begin
            mul$1$a = p$0$q;
            mul$1$b = op_g$2;
        end
        if ((lane$15 == 1) & act$15) begin
            mul$1$a = p$1$q;
            mul$1$b = op_g$3;
        end
        if ((lane$16 == 1) & act$16) begin
            mul$1$a = p$3$q;
            mul$1$b = op_g$4;
        end
        if ((lane$17 == 1) & act$17) begin
            mul$1$a = p$2$q;
            mul$1$b = op_g$5;
        end
        if ((lane$18 == 1) & act$18) begin
            mul$1$a = p$0$q;
            mul$1$b = op_g$6;
        end
        if ((lane$19 == 1) & act$19) begin
            mul$1$a = p$1$q;
            mul$1$b = op_g$7;
        end
        if ((lane$20 == 1) & act$20) begin
            mul$1$a = p$3$q;
            mul$1$b = op_g$8;
        end
        if ((lane$21 == 1) & act$21) begin
            mul$1$a = p$2$q;
            mul$1$b = op_g$9;
        end
        if ((lane$22 == 1) & act$22) begin
            mul$1$a = p$0$q;
            mul$1$b = op_g$10;
        end
        if ((lane$23 == 1) & act$23) begin
            mul$1$a = p$1$q;
            mul$1$b = op_g$11;
        end
        if ((lane$24 == 1) & act$24) begin
            mul$1$a = p$3$q;
            mul$1$b = op_g$12;
        end
        if ((lane$25 == 1) & act$25) begin
            mul$1$a = p$2$q;
            mul$1$b = op_g$13;
        end
        if ((lane$26 == 1) & act$26) begin
            mul$1$a = p$0$q;
            mul$1$b = op_g$14;
        end
        if ((lane$27 == 1) & act$27) begin
            mul$1$a = p$1$q;
            mul$1$b = op_g$15;
        end
        if ((lane$12 == 1) & add$12) begin
            pg$0 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$13 == 1) & add$13) begin
            pg$1 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$14 == 1) & add$14) begin
            pg$2 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$15 == 1) & add$15) begin
            pg$3 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$16 == 1) & add$16) begin
            pg$4 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$17 == 1) & add$17) begin
            pg$5 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$18 == 1) & add$18) begin
            pg$6 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$19 == 1) & add$19) begin
            pg$7 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$20 == 1) & add$20) begin
            pg$8 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$21 == 1) & add$21) begin
            pg$9 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$22 == 1) & add$22) begin
            pg$10 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$23 == 1) & add$23) begin
            pg$11 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$24 == 1) & add$24) begin
            pg$12 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$25 == 1) & add$25) begin
            pg$13 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$26 == 1) & add$26) begin
            pg$14 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$27 == 1) & add$27) begin
            pg$15 = mul$1$p[(32'h0)+:(57)];
        end
        if ((lane$28 == 1) & act$28) begin
            mul$1$a = ddx$0;
            mul$1$b = op_s$0;
        end
        if ((lane$29 == 1) & act$29) begin
            mul$1$a = ddy$0;
            mul$1$b = op_s$1;
        end
        if ((lane$30 == 1) & act$30) begin
            mul$1$a = ddx$0;
            mul$1$b = op_q$0;
        end
        if ((lane$31 == 1) & act$31) begin
            mul$1$a = ddx$1;
            mul$1$b = op_s$2;
        end
        if ((lane$32 == 1) & act$32) begin
            mul$1$a = ddy$1;
            mul$1$b = op_s$3;
        end
        if ((lane$33 == 1) & act$33) begin
            mul$1$a = ddx$1;
            mul$1$b = op_q$1;
        end
        if ((lane$34 == 1) & act$34) begin
            mul$1$a = ddx$2;
            mul$1$b = op_s$4;
        end
        if ((lane$35 == 1) & act$35) begin
            mul$1$a = ddy$2;
            mul$1$b = op_s$5;
        end
        if ((lane$36 == 1) & act$36) begin
            mul$1$a = ddx$2;
            mul$1$b = op_q$2;
        end
        if ((lane$37 == 1) & act$37) begin
            mul$1$a = ddx$3;
            mul$1$b = op_s$6;
        end
        if ((lane$38 == 1) & act$38) begin
            mul$1$a = ddy$3;
            mul$1$b = op_s$7;
        end
        if ((lane$39 == 1) & act$39) begin
            mul$1$a = ddx$3;
            mul$1$b = op_q$3;
        end
        if ((lane$40 == 1) & act$40) begin
            mul$1$a = ddx$0;
            mul$1$b = op_s$8;
        end
        if ((lane$41 == 1) & act$41) begin
            mul$1$a = ddy$0;
            mul$1$b = op_s$9;
        end
        if ((lane$42 == 1) & act$42) begin
            mul$1$a = ddx$0;
            mul$1$b = op_q$4;
        end
        if ((lane$43 == 1) & act$43) begin
            mul$1$a = ddx$1;
            mul$1$b = op_s$10;
        end
        if ((lane$44 == 1) & act$44) begin
            mul$1$a = ddy$1;
            mul$1$b = op_s$11;
        end
        if ((lane$45 == 1) & act$45) begin
            mul$1$a = ddx$1;
            mul$1$b = op_q$5;
        end
        if ((lane$46 == 1) & act$46) begin
            mul$1$a = ddx$2;
            mul$1$b = op_s$12;
        end
        if ((lane$47 == 1) & act$47) begin
            mul$1$a = ddy$2;
            mul$1$b = op_s$13;
        end
        if ((lane$48 == 1) & act$48) begin
            mul$1$a = ddx$2;
            mul$1$b = op_q$6;
        end
        if ((lane$49 == 1) & act$49) begin
            mul$1$a = ddx$3;
            mul$1$b = op_s$14;
        end
        if ((lane$50 == 1) & act$50) begin
            mul$1$a = ddy$3;
            mul$1$b = op_s$15;
        end
        if ((lane$51 == 1) & act$51) begin
            mul$1$a = ddx$3;
            mul$1$b = op_q$7;
        end
        if ((lane$52 == 1) & act$52) begin
            mul$1$a = ddx$0;
            mul$1$b = op_s$16;
        end
        if ((lane$53 == 1) & act$53) begin
            mul$1$a = ddy$0;
            mul$1$b = op_s$17;
        end
        if ((lane$54 == 1) & act$54) begin
            mul$1$a = ddx$0;
            mul$1$b = op_q$8;
        end
        if ((lane$55 == 1) & act$55) begin
            mul$1$a = ddx$1;
            mul$1$b = op_s$18;
        end
        if ((lane$56 == 1) & act$56) begin
            mul$1$a = ddy$1;
            mul$1$b = op_s$19;
        end
        if ((lane$57 == 1) & act$57) begin
            mul$1$a = ddx$1;
            mul$1$b = op_q$9;
        end
        if ((lane$58 == 1) & act$58) begin
            mul$1$a = ddx$2;
            mul$1$b = op_s$20;
        end
        if ((lane$59 == 1) & act$59) begin
            mul$1$a = ddy$2;
            mul$1$b = op_s$21;
        end
        if ((lane$60 == 1) & act$60) begin
            mul$1$a = ddx$2;
            mul$1$b = op_q$10;
        end
        if ((lane$61 == 1) & act$61) begin
            mul$1$a = ddx$3;
            mul$1$b = op_s$22;
        end
        if ((lane$62 == 1) & act$62) begin
            mul$1$a = ddy$3;
            mul$1$b = op_s$23;
        end
        if ((lane$63 == 1) & act$63) begin
            mul$1$a = ddx$3;
            mul$1$b = op_q$11;
        end
        if ((lane$28 == 1) & add$28) begin
            ps$0 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$29 == 1) & add$29) begin
            ps$1 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$30 == 1) & add$30) begin
            ps$2 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$31 == 1) & add$31) begin
            ps$3 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$32 == 1) & add$32) begin
            ps$4 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$33 == 1) & add$33) begin
            ps$5 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$34 == 1) & add$34) begin
            ps$6 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$35 == 1) & add$35) begin
            ps$7 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$36 == 1) & add$36) begin
            ps$8 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$37 == 1) & add$37) begin
            ps$9 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$38 == 1) & add$38) begin
            ps$10 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$39 == 1) & add$39) begin
            ps$11 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$40 == 1) & add$40) begin
            ps$12 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$41 == 1) & add$41) begin
            ps$13 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$42 == 1) & add$42) begin
            ps$14 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$43 == 1) & add$43) begin
            ps$15 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$44 == 1) & add$44) begin
            ps$16 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$45 == 1) & add$45) begin
            ps$17 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$46 == 1) & add$46) begin
            ps$18 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$47 == 1) & add$47) begin
            ps$19 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$48 == 1) & add$48) begin
            ps$20 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$49 == 1) & add$49) begin
            ps$21 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$50 == 1) & add$50) begin
            ps$22 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$51 == 1) & add$51) begin
            ps$23 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$52 == 1) & add$52) begin
            ps$24 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$53 == 1) & add$53) begin
            ps$25 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$54 == 1) & add$54) begin
            ps$26 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$55 == 1) & add$55) begin
            ps$27 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$56 == 1) & add$56) begin
            ps$28 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$57 == 1) & add$57) begin
            ps$29 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$58 == 1) & add$58) begin
            ps$30 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$59 == 1) & add$59) begin
            ps$31 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$60 == 1) & add$60) begin
            ps$32 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$61 == 1) & add$61) begin
            ps$33 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$62 == 1) & add$62) begin
            ps$34 = mul$1$p[(32'h0)+:(40)];
        end
        if ((lane$63 == 1) & add$63) begin
            ps$35 = mul$1$p[(32'h0)+:(40)];
        end
        mul$2$en = run;
        if ((lane$0 == 2) & act$0) begin
            mul$2$a = g0$kdx$0[(32'h0)+:(57)];
            mul$2$b = g0$kdy$1[(32'h0)+:(19)];
        end
        if ((lane$1 == 2) & act$1) begin
            mul$2$a = g0$kdx$1[(32'h0)+:(57)];
            mul$2$b = g0$kdy$0[(32'h0)+:(19)];
        end
        if ((lane$0 == 2) & add$0) begin
            pa$0 = mul$2$p[(32'h0)+:(34)];
        end
        if ((lane$1 == 2) & add$1) begin
            pa$1 = mul$2$p[(32'h0)+:(34)];
        end
        if ((lane$2 == 2) & act$2) begin
            mul$2$a = g0$edy$0;
            mul$2$b = g0$xf$0;
        end
        if ((lane$3 == 2) & act$3) begin
            mul$2$a = g0$edx$0[(32'h0)+:(57)];
            mul$2$b = g0$toff$0;
        end
        if ((lane$4 == 2) & act$4) begin
            mul$2$a = g0$edy$1;
            mul$2$b = g0$xf$1;
        end
        if ((lane$5 == 2) & act$5) begin
            mul$2$a = g0$edx$1[(32'h0)+:(57)];
            mul$2$b = g0$toff$1;
        end
        if ((lane$6 == 2) & act$6) begin
            mul$2$a = g0$edy$2;
            mul$2$b = g0$xf$2;
        end
        if ((lane$7 == 2) & act$7) begin
            mul$2$a = g0$edx$2[(32'h0)+:(57)];
            mul$2$b = g0$toff$2;
        end
        if ((lane$2 == 2) & add$2) begin
            pn$0 = mul$2$p;
        end
        if ((lane$3 == 2) & add$3) begin
            pn$1 = mul$2$p;
        end
        if ((lane$4 == 2) & add$4) begin
            pn$2 = mul$2$p;
        end
        if ((lane$5 == 2) & add$5) begin
            pn$3 = mul$2$p;
        end
        if ((lane$6 == 2) & add$6) begin
            pn$4 = mul$2$p;
        end
        if ((lane$7 == 2) & add$7) begin
            pn$5 = mul$2$p;
        end
        if ((lane$8 == 2) & act$8) begin
            mul$2$a = mant_s$q;
            mul$2$b = op_e$0;
        end
        if ((lane$8 == 2) & add$8) begin
            pe$0 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$9 == 2) & act$9) begin
            mul$2$a = mant_s$q;
            mul$2$b = op_e$1;
        end
        if ((lane$9 == 2) & add$9) begin
            pe$1 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$10 == 2) & act$10) begin
            mul$2$a = mant_s$q;
            mul$2$b = op_e$2;
        end
        if ((lane$10 == 2) & add$10) begin
            pe$2 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$11 == 2) & act$11) begin
            mul$2$a = mant_s$q;
            mul$2$b = op_e$3;
        end
        if ((lane$11 == 2) & add$11) begin
            pe$3 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$12 == 2) & act$12) begin
            mul$2$a = p$3$q;
            mul$2$b = op_g$0;
        end
        if ((lane$13 == 2) & act$13) begin
            mul$2$a = p$2$q;
            mul$2$b = op_g$1;
        end
        if ((lane$14 == 2) & act$14) begin
            mul$2$a = p$0$q;
            mul$2$b = op_g$2;
        end
        if ((lane$15 == 2) & act$15) begin
            mul$2$a = p$1$q;
            mul$2$b = op_g$3;
        end
        if ((lane$16 == 2) & act$16) begin
            mul$2$a = p$3$q;
            mul$2$b = op_g$4;
        end
        if ((lane$17 == 2) & act$17) begin
            mul$2$a = p$2$q;
            mul$2$b = op_g$5;
        end
        if ((lane$18 == 2) & act$18) begin
            mul$2$a = p$0$q;
            mul$2$b = op_g$6;
        end
        if ((lane$19 == 2) & act$19) begin
            mul$2$a = p$1$q;
            mul$2$b = op_g$7;
        end
        if ((lane$20 == 2) & act$20) begin
            mul$2$a = p$3$q;
            mul$2$b = op_g$8;
        end
        if ((lane$21 == 2) & act$21) begin
            mul$2$a = p$2$q;
            mul$2$b = op_g$9;
        end
        if ((lane$22 == 2) & act$22) begin
            mul$2$a = p$0$q;
            mul$2$b = op_g$10;
        end
        if ((lane$23 == 2) & act$23) begin
            mul$2$a = p$1$q;
            mul$2$b = op_g$11;
        end
        if ((lane$24 == 2) & act$24) begin
            mul$2$a = p$3$q;
            mul$2$b = op_g$12;
        end
        if ((lane$25 == 2) & act$25) begin
            mul$2$a = p$2$q;
            mul$2$b = op_g$13;
        end
        if ((lane$26 == 2) & act$26) begin
            mul$2$a = p$0$q;
            mul$2$b = op_g$14;
        end
        if ((lane$27 == 2) & act$27) begin
            mul$2$a = p$1$q;
            mul$2$b = op_g$15;
        end
        if ((lane$12 == 2) & add$12) begin
            pg$0 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$13 == 2) & add$13) begin
            pg$1 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$14 == 2) & add$14) begin
            pg$2 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$15 == 2) & add$15) begin
            pg$3 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$16 == 2) & add$16) begin
            pg$4 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$17 == 2) & add$17) begin
            pg$5 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$18 == 2) & add$18) begin
            pg$6 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$19 == 2) & add$19) begin
            pg$7 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$20 == 2) & add$20) begin
            pg$8 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$21 == 2) & add$21) begin
            pg$9 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$22 == 2) & add$22) begin
            pg$10 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$23 == 2) & add$23) begin
            pg$11 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$24 == 2) & add$24) begin
            pg$12 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$25 == 2) & add$25) begin
            pg$13 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$26 == 2) & add$26) begin
            pg$14 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$27 == 2) & add$27) begin
            pg$15 = mul$2$p[(32'h0)+:(57)];
        end
        if ((lane$28 == 2) & act$28) begin
            mul$2$a = ddx$0;
            mul$2$b = op_s$0;
        end
        if ((lane$29 == 2) & act$29) begin
            mul$2$a = ddy$0;
            mul$2$b = op_s$1;
        end
        if ((lane$30 == 2) & act$30) begin
            mul$2$a = ddx$0;
            mul$2$b = op_q$0;
        end
        if ((lane$31 == 2) & act$31) begin
            mul$2$a = ddx$1;
            mul$2$b = op_s$2;
        end
        if ((lane$32 == 2) & act$32) begin
            mul$2$a = ddy$1;
            mul$2$b = op_s$3;
        end
        if ((lane$33 == 2) & act$33) begin
            mul$2$a = ddx$1;
            mul$2$b = op_q$1;
        end
        if ((lane$34 == 2) & act$34) begin
            mul$2$a = ddx$2;
            mul$2$b = op_s$4;
        end
        if ((lane$35 == 2) & act$35) begin
            mul$2$a = ddy$2;
            mul$2$b = op_s$5;
        end
        if ((lane$36 == 2) & act$36) begin
            mul$2$a = ddx$2;
            mul$2$b = op_q$2;
        end
        if ((lane$37 == 2) & act$37) begin
            mul$2$a = ddx$3;
            mul$2$b = op_s$6;
        end
        if ((lane$38 == 2) & act$38) begin
            mul$2$a = ddy$3;
            mul$2$b = op_s$7;
        end
        if ((lane$39 == 2) & act$39) begin
            mul$2$a = ddx$3;
            mul$2$b = op_q$3;
        end
        if ((lane$40 == 2) & act$40) begin
            mul$2$a = ddx$0;
            mul$2$b = op_s$8;
        end
        if ((lane$41 == 2) & act$41) begin
            mul$2$a = ddy$0;
            mul$2$b = op_s$9;
        end
        if ((lane$42 == 2) & act$42) begin
            mul$2$a = ddx$0;
            mul$2$b = op_q$4;
        end
        if ((lane$43 == 2) & act$43) begin
            mul$2$a = ddx$1;
            mul$2$b = op_s$10;
        end
        if ((lane$44 == 2) & act$44) begin
            mul$2$a = ddy$1;
            mul$2$b = op_s$11;
        end
        if ((lane$45 == 2) & act$45) begin
            mul$2$a = ddx$1;
            mul$2$b = op_q$5;
        end
        if ((lane$46 == 2) & act$46) begin
            mul$2$a = ddx$2;
            mul$2$b = op_s$12;
        end
        if ((lane$47 == 2) & act$47) begin
            mul$2$a = ddy$2;
            mul$2$b = op_s$13;
        end
        if ((lane$48 == 2) & act$48) begin
            mul$2$a = ddx$2;
            mul$2$b = op_q$6;
        end
        if ((lane$49 == 2) & act$49) begin
            mul$2$a = ddx$3;
            mul$2$b = op_s$14;
        end
        if ((lane$50 == 2) & act$50) begin
            mul$2$a = ddy$3;
            mul$2$b = op_s$15;
        end
        if ((lane$51 == 2) & act$51) begin
            mul$2$a = ddx$3;
            mul$2$b = op_q$7;
        end
        if ((lane$52 == 2) & act$52) begin
            mul$2$a = ddx$0;
            mul$2$b = op_s$16;
        end
        if ((lane$53 == 2) & act$53) begin
            mul$2$a = ddy$0;
            mul$2$b = op_s$17;
        end
        if ((lane$54 == 2) & act$54) begin
            mul$2$a = ddx$0;
            mul$2$b = op_q$8;
        end
        if ((lane$55 == 2) & act$55) begin
            mul$2$a = ddx$1;
            mul$2$b = op_s$18;
        end
        if ((lane$56 == 2) & act$56) begin
            mul$2$a = ddy$1;
            mul$2$b = op_s$19;
        end
        if ((lane$57 == 2) & act$57) begin
            mul$2$a = ddx$1;
            mul$2$b = op_q$9;
        end
        if ((lane$58 == 2) & act$58) begin
            mul$2$a = ddx$2;
            mul$2$b = op_s$20;
        end
        if ((lane$59 == 2) & act$59) begin
            mul$2$a = ddy$2;
            mul$2$b = op_s$21;
        end
        if ((lane$60 == 2) & act$60) begin
            mul$2$a = ddx$2;
            mul$2$b = op_q$10;
        end
        if ((lane$61 == 2) & act$61) begin
            mul$2$a = ddx$3;
            mul$2$b = op_s$22;
        end
        if ((lane$62 == 2) & act$62) begin
            mul$2$a = ddy$3;
            mul$2$b = op_s$23;
        end
        if ((lane$63 == 2) & act$63) begin
            mul$2$a = ddx$3;
            mul$2$b = op_q$11;
        end
        if ((lane$28 == 2) & add$28) begin
            ps$0 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$29 == 2) & add$29) begin
            ps$1 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$30 == 2) & add$30) begin
            ps$2 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$31 == 2) & add$31) begin
            ps$3 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$32 == 2) & add$32) begin
            ps$4 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$33 == 2) & add$33) begin
            ps$5 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$34 == 2) & add$34) begin
            ps$6 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$35 == 2) & add$35) begin
            ps$7 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$36 == 2) & add$36) begin
            ps$8 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$37 == 2) & add$37) begin
            ps$9 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$38 == 2) & add$38) begin
            ps$10 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$39 == 2) & add$39) begin
            ps$11 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$40 == 2) & add$40) begin
            ps$12 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$41 == 2) & add$41) begin
            ps$13 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$42 == 2) & add$42) begin
            ps$14 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$43 == 2) & add$43) begin
            ps$15 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$44 == 2) & add$44) begin
            ps$16 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$45 == 2) & add$45) begin
            ps$17 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$46 == 2) & add$46) begin
            ps$18 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$47 == 2) & add$47) begin
            ps$19 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$48 == 2) & add$48) begin
            ps$20 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$49 == 2) & add$49) begin
            ps$21 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$50 == 2) & add$50) begin
            ps$22 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$51 == 2) & add$51) begin
            ps$23 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$52 == 2) & add$52) begin
            ps$24 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$53 == 2) & add$53) begin
            ps$25 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$54 == 2) & add$54) begin
            ps$26 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$55 == 2) & add$55) begin
            ps$27 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$56 == 2) & add$56) begin
            ps$28 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$57 == 2) & add$57) begin
            ps$29 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$58 == 2) & add$58) begin
            ps$30 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$59 == 2) & add$59) begin
            ps$31 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$60 == 2) & add$60) begin
            ps$32 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$61 == 2) & add$61) begin
            ps$33 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$62 == 2) & add$62) begin
            ps$34 = mul$2$p[(32'h0)+:(40)];
        end
        if ((lane$63 == 2) & add$63) begin
            ps$35 = mul$2$p[(32'h0)+:(40)];
        end
        mul$3$en = run;
        if ((lane$0 == 3) & act$0) begin
            mul$3$a = g0$kdx$0[(32'h0)+:(57)];
            mul$3$b = g0$kdy$1[(32'h0)+:(19)];
        end
        if ((lane$1 == 3) & act$1) begin
            mul$3$a = g0$kdx$1[(32'h0)+:(57)];
            mul$3$b = g0$kdy$0[(32'h0)+:(19)];
        end
        if ((lane$0 == 3) & add$0) begin
            pa$0 = mul$3$p[(32'h0)+:(34)];
        end
        if ((lane$1 == 3) & add$1) begin
            pa$1 = mul$3$p[(32'h0)+:(34)];
        end
        if ((lane$2 == 3) & act$2) begin
            mul$3$a = g0$edy$0;
            mul$3$b = g0$xf$0;
        end
        if ((lane$3 == 3) & act$3) begin
            mul$3$a = g0$edx$0[(32'h0)+:(57)];
            mul$3$b = g0$toff$0;
        end
        if ((lane$4 == 3) & act$4) begin
            mul$3$a = g0$edy$1;
            mul$3$b = g0$xf$1;
        end
        if ((lane$5 == 3) & act$5) begin
            mul$3$a = g0$edx$1[(32'h0)+:(57)];
            mul$3$b = g0$toff$1;
        end
        if ((lane$6 == 3) & act$6) begin
            mul$3$a = g0$edy$2;
            mul$3$b = g0$xf$2;
        end
        if ((lane$7 == 3) & act$7) begin
            mul$3$a = g0$edx$2[(32'h0)+:(57)];
            mul$3$b = g0$toff$2;
        end
        if ((lane$2 == 3) & add$2) begin
            pn$0 = mul$3$p;
        end
        if ((lane$3 == 3) & add$3) begin
            pn$1 = mul$3$p;
        end
        if ((lane$4 == 3) & add$4) begin
            pn$2 = mul$3$p;
        end
        if ((lane$5 == 3) & add$5) begin
            pn$3 = mul$3$p;
        end
        if ((lane$6 == 3) & add$6) begin
            pn$4 = mul$3$p;
        end
        if ((lane$7 == 3) & add$7) begin
            pn$5 = mul$3$p;
        end
        if ((lane$8 == 3) & act$8) begin
            mul$3$a = mant_s$q;
            mul$3$b = op_e$0;
        end
        if ((lane$8 == 3) & add$8) begin
            pe$0 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$9 == 3) & act$9) begin
            mul$3$a = mant_s$q;
            mul$3$b = op_e$1;
        end
        if ((lane$9 == 3) & add$9) begin
            pe$1 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$10 == 3) & act$10) begin
            mul$3$a = mant_s$q;
            mul$3$b = op_e$2;
        end
        if ((lane$10 == 3) & add$10) begin
            pe$2 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$11 == 3) & act$11) begin
            mul$3$a = mant_s$q;
            mul$3$b = op_e$3;
        end
        if ((lane$11 == 3) & add$11) begin
            pe$3 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$12 == 3) & act$12) begin
            mul$3$a = p$3$q;
            mul$3$b = op_g$0;
        end
        if ((lane$13 == 3) & act$13) begin
            mul$3$a = p$2$q;
            mul$3$b = op_g$1;
        end
        if ((lane$14 == 3) & act$14) begin
            mul$3$a = p$0$q;
            mul$3$b = op_g$2;
        end
        if ((lane$15 == 3) & act$15) begin
            mul$3$a = p$1$q;
            mul$3$b = op_g$3;
        end
        if ((lane$16 == 3) & act$16) begin
            mul$3$a = p$3$q;
            mul$3$b = op_g$4;
        end
        if ((lane$17 == 3) & act$17) begin
            mul$3$a = p$2$q;
            mul$3$b = op_g$5;
        end
        if ((lane$18 == 3) & act$18) begin
            mul$3$a = p$0$q;
            mul$3$b = op_g$6;
        end
        if ((lane$19 == 3) & act$19) begin
            mul$3$a = p$1$q;
            mul$3$b = op_g$7;
        end
        if ((lane$20 == 3) & act$20) begin
            mul$3$a = p$3$q;
            mul$3$b = op_g$8;
        end
        if ((lane$21 == 3) & act$21) begin
            mul$3$a = p$2$q;
            mul$3$b = op_g$9;
        end
        if ((lane$22 == 3) & act$22) begin
            mul$3$a = p$0$q;
            mul$3$b = op_g$10;
        end
        if ((lane$23 == 3) & act$23) begin
            mul$3$a = p$1$q;
            mul$3$b = op_g$11;
        end
        if ((lane$24 == 3) & act$24) begin
            mul$3$a = p$3$q;
            mul$3$b = op_g$12;
        end
        if ((lane$25 == 3) & act$25) begin
            mul$3$a = p$2$q;
            mul$3$b = op_g$13;
        end
        if ((lane$26 == 3) & act$26) begin
            mul$3$a = p$0$q;
            mul$3$b = op_g$14;
        end
        if ((lane$27 == 3) & act$27) begin
            mul$3$a = p$1$q;
            mul$3$b = op_g$15;
        end
        if ((lane$12 == 3) & add$12) begin
            pg$0 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$13 == 3) & add$13) begin
            pg$1 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$14 == 3) & add$14) begin
            pg$2 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$15 == 3) & add$15) begin
            pg$3 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$16 == 3) & add$16) begin
            pg$4 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$17 == 3) & add$17) begin
            pg$5 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$18 == 3) & add$18) begin
            pg$6 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$19 == 3) & add$19) begin
            pg$7 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$20 == 3) & add$20) begin
            pg$8 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$21 == 3) & add$21) begin
            pg$9 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$22 == 3) & add$22) begin
            pg$10 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$23 == 3) & add$23) begin
            pg$11 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$24 == 3) & add$24) begin
            pg$12 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$25 == 3) & add$25) begin
            pg$13 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$26 == 3) & add$26) begin
            pg$14 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$27 == 3) & add$27) begin
            pg$15 = mul$3$p[(32'h0)+:(57)];
        end
        if ((lane$28 == 3) & act$28) begin
            mul$3$a = ddx$0;
            mul$3$b = op_s$0;
        end
        if ((lane$29 == 3) & act$29) begin
            mul$3$a = ddy$0;
            mul$3$b = op_s$1;
        end
        if ((lane$30 == 3) & act$30) begin
            mul$3$a = ddx$0;
            mul$3$b = op_q$0;
        end
        if ((lane$31 == 3) & act$31) begin
            mul$3$a = ddx$1;
            mul$3$b = op_s$2;
        end
        if ((lane$32 == 3) & act$32) begin
            mul$3$a = ddy$1;
            mul$3$b = op_s$3;
        end
        if ((lane$33 == 3) & act$33) begin
            mul$3$a = ddx$1;
            mul$3$b = op_q$1;
        end
        if ((lane$34 == 3) & act$34) begin
            mul$3$a = ddx$2;
            mul$3$b = op_s$4;
        end
        if ((lane$35 == 3) & act$35) begin
            mul$3$a = ddy$2;
            mul$3$b = op_s$5;
        end
        if ((lane$36 == 3) & act$36) begin
            mul$3$a = ddx$2;
            mul$3$b = op_q$2;
        end
        if ((lane$37 == 3) & act$37) begin
            mul$3$a = ddx$3;
            mul$3$b = op_s$6;
        end
        if ((lane$38 == 3) & act$38) begin
            mul$3$a = ddy$3;
            mul$3$b = op_s$7;
        end
        if ((lane$39 == 3) & act$39) begin
            mul$3$a = ddx$3;
            mul$3$b = op_q$3;
        end
        if ((lane$40 == 3) & act$40) begin
            mul$3$a = ddx$0;
            mul$3$b = op_s$8;
        end
        if ((lane$41 == 3) & act$41) begin
            mul$3$a = ddy$0;
            mul$3$b = op_s$9;
        end
        if ((lane$42 == 3) & act$42) begin
            mul$3$a = ddx$0;
            mul$3$b = op_q$4;
        end
        if ((lane$43 == 3) & act$43) begin
            mul$3$a = ddx$1;
            mul$3$b = op_s$10;
        end
        if ((lane$44 == 3) & act$44) begin
            mul$3$a = ddy$1;
            mul$3$b = op_s$11;
        end
        if ((lane$45 == 3) & act$45) begin
            mul$3$a = ddx$1;
            mul$3$b = op_q$5;
        end
        if ((lane$46 == 3) & act$46) begin
            mul$3$a = ddx$2;
            mul$3$b = op_s$12;
        end
        if ((lane$47 == 3) & act$47) begin
            mul$3$a = ddy$2;
            mul$3$b = op_s$13;
        end
        if ((lane$48 == 3) & act$48) begin
            mul$3$a = ddx$2;
            mul$3$b = op_q$6;
        end
        if ((lane$49 == 3) & act$49) begin
            mul$3$a = ddx$3;
            mul$3$b = op_s$14;
        end
        if ((lane$50 == 3) & act$50) begin
            mul$3$a = ddy$3;
            mul$3$b = op_s$15;
        end
        if ((lane$51 == 3) & act$51) begin
            mul$3$a = ddx$3;
            mul$3$b = op_q$7;
        end
        if ((lane$52 == 3) & act$52) begin
            mul$3$a = ddx$0;
            mul$3$b = op_s$16;
        end
        if ((lane$53 == 3) & act$53) begin
            mul$3$a = ddy$0;
            mul$3$b = op_s$17;
        end
        if ((lane$54 == 3) & act$54) begin
            mul$3$a = ddx$0;
            mul$3$b = op_q$8;
        end
        if ((lane$55 == 3) & act$55) begin
            mul$3$a = ddx$1;
            mul$3$b = op_s$18;
        end
        if ((lane$56 == 3) & act$56) begin
            mul$3$a = ddy$1;
            mul$3$b = op_s$19;
        end
        if ((lane$57 == 3) & act$57) begin
            mul$3$a = ddx$1;
            mul$3$b = op_q$9;
        end
        if ((lane$58 == 3) & act$58) begin
            mul$3$a = ddx$2;
            mul$3$b = op_s$20;
        end
        if ((lane$59 == 3) & act$59) begin
            mul$3$a = ddy$2;
            mul$3$b = op_s$21;
        end
        if ((lane$60 == 3) & act$60) begin
            mul$3$a = ddx$2;
            mul$3$b = op_q$10;
        end
        if ((lane$61 == 3) & act$61) begin
            mul$3$a = ddx$3;
            mul$3$b = op_s$22;
        end
        if ((lane$62 == 3) & act$62) begin
            mul$3$a = ddy$3;
            mul$3$b = op_s$23;
        end
        if ((lane$63 == 3) & act$63) begin
            mul$3$a = ddx$3;
            mul$3$b = op_q$11;
        end
        if ((lane$28 == 3) & add$28) begin
            ps$0 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$29 == 3) & add$29) begin
            ps$1 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$30 == 3) & add$30) begin
            ps$2 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$31 == 3) & add$31) begin
            ps$3 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$32 == 3) & add$32) begin
            ps$4 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$33 == 3) & add$33) begin
            ps$5 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$34 == 3) & add$34) begin
            ps$6 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$35 == 3) & add$35) begin
            ps$7 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$36 == 3) & add$36) begin
            ps$8 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$37 == 3) & add$37) begin
            ps$9 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$38 == 3) & add$38) begin
            ps$10 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$39 == 3) & add$39) begin
            ps$11 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$40 == 3) & add$40) begin
            ps$12 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$41 == 3) & add$41) begin
            ps$13 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$42 == 3) & add$42) begin
            ps$14 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$43 == 3) & add$43) begin
            ps$15 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$44 == 3) & add$44) begin
            ps$16 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$45 == 3) & add$45) begin
            ps$17 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$46 == 3) & add$46) begin
            ps$18 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$47 == 3) & add$47) begin
            ps$19 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$48 == 3) & add$48) begin
            ps$20 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$49 == 3) & add$49) begin
            ps$21 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$50 == 3) & add$50) begin
            ps$22 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$51 == 3) & add$51) begin
            ps$23 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$52 == 3) & add$52) begin
            ps$24 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$53 == 3) & add$53) begin
            ps$25 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$54 == 3) & add$54) begin
            ps$26 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$55 == 3) & add$55) begin
            ps$27 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$56 == 3) & add$56) begin
            ps$28 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$57 == 3) & add$57) begin
            ps$29 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$58 == 3) & add$58) begin
            ps$30 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$59 == 3) & add$59) begin
            ps$31 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$60 == 3) & add$60) begin
            ps$32 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$61 == 3) & add$61) begin
            ps$33 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$62 == 3) & add$62) begin
            ps$34 = mul$3$p[(32'h0)+:(40)];
        end
        if ((lane$63 == 3) & add$63) begin
            ps$35 = mul$3$p[(32'h0)+:(40)];
        end
        mul$4$en = run;
        if ((lane$0 == 4) & act$0) begin
            mul$4$a = g0$kdx$0[(32'h0)+:(57)];
            mul$4$b = g0$kdy$1[(32'h0)+:(19)];
        end
        if ((lane$1 == 4) & act$1) begin
            mul$4$a = g0$kdx$1[(32'h0)+:(57)];
            mul$4$b = g0$kdy$0[(32'h0)+:(19)];
        end
        if ((lane$0 == 4) & add$0) begin
            pa$0 = mul$4$p[(32'h0)+:(34)];
        end
        if ((lane$1 == 4) & add$1) begin
            pa$1 = mul$4$p[(32'h0)+:(34)];
        end
        if ((lane$2 == 4) & act$2) begin
            mul$4$a = g0$edy$0;
            mul$4$b = g0$xf$0;
        end
        if ((lane$3 == 4) & act$3) begin
            mul$4$a = g0$edx$0[(32'h0)+:(57)];
            mul$4$b = g0$toff$0;
        end
        if ((lane$4 == 4) & act$4) begin
            mul$4$a = g0$edy$1;
            mul$4$b = g0$xf$1;
        end
        if ((lane$5 == 4) & act$5) begin
            mul$4$a = g0$edx$1[(32'h0)+:(57)];
            mul$4$b = g0$toff$1;
        end
        if ((lane$6 == 4) & act$6) begin
            mul$4$a = g0$edy$2;
            mul$4$b = g0$xf$2;
        end
        if ((lane$7 == 4) & act$7) begin
            mul$4$a = g0$edx$2[(32'h0)+:(57)];
            mul$4$b = g0$toff$2;
        end
        if ((lane$2 == 4) & add$2) begin
            pn$0 = mul$4$p;
        end
        if ((lane$3 == 4) & add$3) begin
            pn$1 = mul$4$p;
        end
        if ((lane$4 == 4) & add$4) begin
            pn$2 = mul$4$p;
        end
        if ((lane$5 == 4) & add$5) begin
            pn$3 = mul$4$p;
        end
        if ((lane$6 == 4) & add$6) begin
            pn$4 = mul$4$p;
        end
        if ((lane$7 == 4) & add$7) begin
            pn$5 = mul$4$p;
        end
        if ((lane$8 == 4) & act$8) begin
            mul$4$a = mant_s$q;
            mul$4$b = op_e$0;
        end
        if ((lane$8 == 4) & add$8) begin
            pe$0 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$9 == 4) & act$9) begin
            mul$4$a = mant_s$q;
            mul$4$b = op_e$1;
        end
        if ((lane$9 == 4) & add$9) begin
            pe$1 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$10 == 4) & act$10) begin
            mul$4$a = mant_s$q;
            mul$4$b = op_e$2;
        end
        if ((lane$10 == 4) & add$10) begin
            pe$2 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$11 == 4) & act$11) begin
            mul$4$a = mant_s$q;
            mul$4$b = op_e$3;
        end
        if ((lane$11 == 4) & add$11) begin
            pe$3 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$12 == 4) & act$12) begin
            mul$4$a = p$3$q;
            mul$4$b = op_g$0;
        end
        if ((lane$13 == 4) & act$13) begin
            mul$4$a = p$2$q;
            mul$4$b = op_g$1;
        end
        if ((lane$14 == 4) & act$14) begin
            mul$4$a = p$0$q;
            mul$4$b = op_g$2;
        end
        if ((lane$15 == 4) & act$15) begin
            mul$4$a = p$1$q;
            mul$4$b = op_g$3;
        end
        if ((lane$16 == 4) & act$16) begin
            mul$4$a = p$3$q;
            mul$4$b = op_g$4;
        end
        if ((lane$17 == 4) & act$17) begin
            mul$4$a = p$2$q;
            mul$4$b = op_g$5;
        end
        if ((lane$18 == 4) & act$18) begin
            mul$4$a = p$0$q;
            mul$4$b = op_g$6;
        end
        if ((lane$19 == 4) & act$19) begin
            mul$4$a = p$1$q;
            mul$4$b = op_g$7;
        end
        if ((lane$20 == 4) & act$20) begin
            mul$4$a = p$3$q;
            mul$4$b = op_g$8;
        end
        if ((lane$21 == 4) & act$21) begin
            mul$4$a = p$2$q;
            mul$4$b = op_g$9;
        end
        if ((lane$22 == 4) & act$22) begin
            mul$4$a = p$0$q;
            mul$4$b = op_g$10;
        end
        if ((lane$23 == 4) & act$23) begin
            mul$4$a = p$1$q;
            mul$4$b = op_g$11;
        end
        if ((lane$24 == 4) & act$24) begin
            mul$4$a = p$3$q;
            mul$4$b = op_g$12;
        end
        if ((lane$25 == 4) & act$25) begin
            mul$4$a = p$2$q;
            mul$4$b = op_g$13;
        end
        if ((lane$26 == 4) & act$26) begin
            mul$4$a = p$0$q;
            mul$4$b = op_g$14;
        end
        if ((lane$27 == 4) & act$27) begin
            mul$4$a = p$1$q;
            mul$4$b = op_g$15;
        end
        if ((lane$12 == 4) & add$12) begin
            pg$0 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$13 == 4) & add$13) begin
            pg$1 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$14 == 4) & add$14) begin
            pg$2 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$15 == 4) & add$15) begin
            pg$3 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$16 == 4) & add$16) begin
            pg$4 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$17 == 4) & add$17) begin
            pg$5 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$18 == 4) & add$18) begin
            pg$6 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$19 == 4) & add$19) begin
            pg$7 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$20 == 4) & add$20) begin
            pg$8 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$21 == 4) & add$21) begin
            pg$9 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$22 == 4) & add$22) begin
            pg$10 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$23 == 4) & add$23) begin
            pg$11 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$24 == 4) & add$24) begin
            pg$12 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$25 == 4) & add$25) begin
            pg$13 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$26 == 4) & add$26) begin
            pg$14 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$27 == 4) & add$27) begin
            pg$15 = mul$4$p[(32'h0)+:(57)];
        end
        if ((lane$28 == 4) & act$28) begin
            mul$4$a = ddx$0;
            mul$4$b = op_s$0;
        end
        if ((lane$29 == 4) & act$29) begin
            mul$4$a = ddy$0;
            mul$4$b = op_s$1;
        end
        if ((lane$30 == 4) & act$30) begin
            mul$4$a = ddx$0;
            mul$4$b = op_q$0;
        end
        if ((lane$31 == 4) & act$31) begin
            mul$4$a = ddx$1;
            mul$4$b = op_s$2;
        end
        if ((lane$32 == 4) & act$32) begin
            mul$4$a = ddy$1;
            mul$4$b = op_s$3;
        end
        if ((lane$33 == 4) & act$33) begin
            mul$4$a = ddx$1;
            mul$4$b = op_q$1;
        end
        if ((lane$34 == 4) & act$34) begin
            mul$4$a = ddx$2;
            mul$4$b = op_s$4;
        end
        if ((lane$35 == 4) & act$35) begin
            mul$4$a = ddy$2;
            mul$4$b = op_s$5;
        end
        if ((lane$36 == 4) & act$36) begin
            mul$4$a = ddx$2;
            mul$4$b = op_q$2;
        end
        if ((lane$37 == 4) & act$37) begin
            mul$4$a = ddx$3;
            mul$4$b = op_s$6;
        end
        if ((lane$38 == 4) & act$38) begin
            mul$4$a = ddy$3;
            mul$4$b = op_s$7;
        end
        if ((lane$39 == 4) & act$39) begin
            mul$4$a = ddx$3;
            mul$4$b = op_q$3;
        end
        if ((lane$40 == 4) & act$40) begin
            mul$4$a = ddx$0;
            mul$4$b = op_s$8;
        end
        if ((lane$41 == 4) & act$41) begin
            mul$4$a = ddy$0;
            mul$4$b = op_s$9;
        end
        if ((lane$42 == 4) & act$42) begin
            mul$4$a = ddx$0;
            mul$4$b = op_q$4;
        end
        if ((lane$43 == 4) & act$43) begin
            mul$4$a = ddx$1;
            mul$4$b = op_s$10;
        end
        if ((lane$44 == 4) & act$44) begin
            mul$4$a = ddy$1;
            mul$4$b = op_s$11;
        end
        if ((lane$45 == 4) & act$45) begin
            mul$4$a = ddx$1;
            mul$4$b = op_q$5;
        end
        if ((lane$46 == 4) & act$46) begin
            mul$4$a = ddx$2;
            mul$4$b = op_s$12;
        end
        if ((lane$47 == 4) & act$47) begin
            mul$4$a = ddy$2;
            mul$4$b = op_s$13;
        end
        if ((lane$48 == 4) & act$48) begin
            mul$4$a = ddx$2;
            mul$4$b = op_q$6;
        end
        if ((lane$49 == 4) & act$49) begin
            mul$4$a = ddx$3;
            mul$4$b = op_s$14;
        end
        if ((lane$50 == 4) & act$50) begin
            mul$4$a = ddy$3;
            mul$4$b = op_s$15;
        end
        if ((lane$51 == 4) & act$51) begin
            mul$4$a = ddx$3;
            mul$4$b = op_q$7;
        end
        if ((lane$52 == 4) & act$52) begin
            mul$4$a = ddx$0;
            mul$4$b = op_s$16;
        end
        if ((lane$53 == 4) & act$53) begin
            mul$4$a = ddy$0;
            mul$4$b = op_s$17;
        end
        if ((lane$54 == 4) & act$54) begin
            mul$4$a = ddx$0;
            mul$4$b = op_q$8;
        end
        if ((lane$55 == 4) & act$55) begin
            mul$4$a = ddx$1;
            mul$4$b = op_s$18;
        end
        if ((lane$56 == 4) & act$56) begin
            mul$4$a = ddy$1;
            mul$4$b = op_s$19;
        end
        if ((lane$57 == 4) & act$57) begin
            mul$4$a = ddx$1;
            mul$4$b = op_q$9;
        end
        if ((lane$58 == 4) & act$58) begin
            mul$4$a = ddx$2;
            mul$4$b = op_s$20;
        end
        if ((lane$59 == 4) & act$59) begin
            mul$4$a = ddy$2;
            mul$4$b = op_s$21;
        end
        if ((lane$60 == 4) & act$60) begin
            mul$4$a = ddx$2;
            mul$4$b = op_q$10;
        end
        if ((lane$61 == 4) & act$61) begin
            mul$4$a = ddx$3;
            mul$4$b = op_s$22;
        end
        if ((lane$62 == 4) & act$62) begin
            mul$4$a = ddy$3;
            mul$4$b = op_s$23;
        end
        if ((lane$63 == 4) & act$63) begin
            mul$4$a = ddx$3;
            mul$4$b = op_q$11;
        end
        if ((lane$28 == 4) & add$28) begin
            ps$0 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$29 == 4) & add$29) begin
            ps$1 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$30 == 4) & add$30) begin
            ps$2 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$31 == 4) & add$31) begin
            ps$3 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$32 == 4) & add$32) begin
            ps$4 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$33 == 4) & add$33) begin
            ps$5 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$34 == 4) & add$34) begin
            ps$6 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$35 == 4) & add$35) begin
            ps$7 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$36 == 4) & add$36) begin
            ps$8 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$37 == 4) & add$37) begin
            ps$9 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$38 == 4) & add$38) begin
            ps$10 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$39 == 4) & add$39) begin
            ps$11 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$40 == 4) & add$40) begin
            ps$12 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$41 == 4) & add$41) begin
            ps$13 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$42 == 4) & add$42) begin
            ps$14 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$43 == 4) & add$43) begin
            ps$15 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$44 == 4) & add$44) begin
            ps$16 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$45 == 4) & add$45) begin
            ps$17 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$46 == 4) & add$46) begin
            ps$18 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$47 == 4) & add$47) begin
            ps$19 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$48 == 4) & add$48) begin
            ps$20 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$49 == 4) & add$49) begin
            ps$21 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$50 == 4) & add$50) begin
            ps$22 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$51 == 4) & add$51) begin
            ps$23 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$52 == 4) & add$52) begin
            ps$24 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$53 == 4) & add$53) begin
            ps$25 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$54 == 4) & add$54) begin
            ps$26 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$55 == 4) & add$55) begin
            ps$27 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$56 == 4) & add$56) begin
            ps$28 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$57 == 4) & add$57) begin
            ps$29 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$58 == 4) & add$58) begin
            ps$30 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$59 == 4) & add$59) begin
            ps$31 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$60 == 4) & add$60) begin
            ps$32 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$61 == 4) & add$61) begin
            ps$33 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$62 == 4) & add$62) begin
            ps$34 = mul$4$p[(32'h0)+:(40)];
        end
        if ((lane$63 == 4) & add$63) begin
            ps$35 = mul$4$p[(32'h0)+:(40)];
        end
        mul$5$en = run;
        if ((lane$0 == 5) & act$0) begin
            mul$5$a = g0$kdx$0[(32'h0)+:(57)];
            mul$5$b = g0$kdy$1[(32'h0)+:(19)];
        end
        if ((lane$1 == 5) & act$1) begin
            mul$5$a = g0$kdx$1[(32'h0)+:(57)];
            mul$5$b = g0$kdy$0[(32'h0)+:(19)];
        end
        if ((lane$0 == 5) & add$0) begin
            pa$0 = mul$5$p[(32'h0)+:(34)];
        end
        if ((lane$1 == 5) & add$1) begin
            pa$1 = mul$5$p[(32'h0)+:(34)];
        end
        if ((lane$2 == 5) & act$2) begin
            mul$5$a = g0$edy$0;
            mul$5$b = g0$xf$0;
        end
        if ((lane$3 == 5) & act$3) begin
            mul$5$a = g0$edx$0[(32'h0)+:(57)];
            mul$5$b = g0$toff$0;
        end
        if ((lane$4 == 5) & act$4) begin
            mul$5$a = g0$edy$1;
            mul$5$b = g0$xf$1;
        end
        if ((lane$5 == 5) & act$5) begin
            mul$5$a = g0$edx$1[(32'h0)+:(57)];
            mul$5$b = g0$toff$1;
        end
        if ((lane$6 == 5) & act$6) begin
            mul$5$a = g0$edy$2;
            mul$5$b = g0$xf$2;
        end
        if ((lane$7 == 5) & act$7) begin
            mul$5$a = g0$edx$2[(32'h0)+:(57)];
            mul$5$b = g0$toff$2;
        end
        if ((lane$2 == 5) & add$2) begin
            pn$0 = mul$5$p;
        end
        if ((lane$3 == 5) & add$3) begin
            pn$1 = mul$5$p;
        end
        if ((lane$4 == 5) & add$4) begin
            pn$2 = mul$5$p;
        end
        if ((lane$5 == 5) & add$5) begin
            pn$3 = mul$5$p;
        end
        if ((lane$6 == 5) & add$6) begin
            pn$4 = mul$5$p;
        end
        if ((lane$7 == 5) & add$7) begin
            pn$5 = mul$5$p;
        end
        if ((lane$8 == 5) & act$8) begin
            mul$5$a = mant_s$q;
            mul$5$b = op_e$0;
        end
        if ((lane$8 == 5) & add$8) begin
            pe$0 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$9 == 5) & act$9) begin
            mul$5$a = mant_s$q;
            mul$5$b = op_e$1;
        end
        if ((lane$9 == 5) & add$9) begin
            pe$1 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$10 == 5) & act$10) begin
            mul$5$a = mant_s$q;
            mul$5$b = op_e$2;
        end
        if ((lane$10 == 5) & add$10) begin
            pe$2 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$11 == 5) & act$11) begin
            mul$5$a = mant_s$q;
            mul$5$b = op_e$3;
        end
        if ((lane$11 == 5) & add$11) begin
            pe$3 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$12 == 5) & act$12) begin
            mul$5$a = p$3$q;
            mul$5$b = op_g$0;
        end
        if ((lane$13 == 5) & act$13) begin
            mul$5$a = p$2$q;
            mul$5$b = op_g$1;
        end
        if ((lane$14 == 5) & act$14) begin
            mul$5$a = p$0$q;
            mul$5$b = op_g$2;
        end
        if ((lane$15 == 5) & act$15) begin
            mul$5$a = p$1$q;
            mul$5$b = op_g$3;
        end
        if ((lane$16 == 5) & act$16) begin
            mul$5$a = p$3$q;
            mul$5$b = op_g$4;
        end
        if ((lane$17 == 5) & act$17) begin
            mul$5$a = p$2$q;
            mul$5$b = op_g$5;
        end
        if ((lane$18 == 5) & act$18) begin
            mul$5$a = p$0$q;
            mul$5$b = op_g$6;
        end
        if ((lane$19 == 5) & act$19) begin
            mul$5$a = p$1$q;
            mul$5$b = op_g$7;
        end
        if ((lane$20 == 5) & act$20) begin
            mul$5$a = p$3$q;
            mul$5$b = op_g$8;
        end
        if ((lane$21 == 5) & act$21) begin
            mul$5$a = p$2$q;
            mul$5$b = op_g$9;
        end
        if ((lane$22 == 5) & act$22) begin
            mul$5$a = p$0$q;
            mul$5$b = op_g$10;
        end
        if ((lane$23 == 5) & act$23) begin
            mul$5$a = p$1$q;
            mul$5$b = op_g$11;
        end
        if ((lane$24 == 5) & act$24) begin
            mul$5$a = p$3$q;
            mul$5$b = op_g$12;
        end
        if ((lane$25 == 5) & act$25) begin
            mul$5$a = p$2$q;
            mul$5$b = op_g$13;
        end
        if ((lane$26 == 5) & act$26) begin
            mul$5$a = p$0$q;
            mul$5$b = op_g$14;
        end
        if ((lane$27 == 5) & act$27) begin
            mul$5$a = p$1$q;
            mul$5$b = op_g$15;
        end
        if ((lane$12 == 5) & add$12) begin
            pg$0 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$13 == 5) & add$13) begin
            pg$1 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$14 == 5) & add$14) begin
            pg$2 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$15 == 5) & add$15) begin
            pg$3 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$16 == 5) & add$16) begin
            pg$4 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$17 == 5) & add$17) begin
            pg$5 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$18 == 5) & add$18) begin
            pg$6 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$19 == 5) & add$19) begin
            pg$7 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$20 == 5) & add$20) begin
            pg$8 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$21 == 5) & add$21) begin
            pg$9 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$22 == 5) & add$22) begin
            pg$10 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$23 == 5) & add$23) begin
            pg$11 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$24 == 5) & add$24) begin
            pg$12 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$25 == 5) & add$25) begin
            pg$13 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$26 == 5) & add$26) begin
            pg$14 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$27 == 5) & add$27) begin
            pg$15 = mul$5$p[(32'h0)+:(57)];
        end
        if ((lane$28 == 5) & act$28) begin
            mul$5$a = ddx$0;
            mul$5$b = op_s$0;
        end
        if ((lane$29 == 5) & act$29) begin
            mul$5$a = ddy$0;
            mul$5$b = op_s$1;
        end
        if ((lane$30 == 5) & act$30) begin
            mul$5$a = ddx$0;
            mul$5$b = op_q$0;
        end
        if ((lane$31 == 5) & act$31) begin
            mul$5$a = ddx$1;
            mul$5$b = op_s$2;
        end
        if ((lane$32 == 5) & act$32) begin
            mul$5$a = ddy$1;
            mul$5$b = op_s$3;
        end
        if ((lane$33 == 5) & act$33) begin
            mul$5$a = ddx$1;
            mul$5$b = op_q$1;
        end
        if ((lane$34 == 5) & act$34) begin
            mul$5$a = ddx$2;
            mul$5$b = op_s$4;
        end
        if ((lane$35 == 5) & act$35) begin
            mul$5$a = ddy$2;
            mul$5$b = op_s$5;
        end
        if ((lane$36 == 5) & act$36) begin
            mul$5$a = ddx$2;
            mul$5$b = op_q$2;
        end
        if ((lane$37 == 5) & act$37) begin
            mul$5$a = ddx$3;
            mul$5$b = op_s$6;
        end
        if ((lane$38 == 5) & act$38) begin
            mul$5$a = ddy$3;
            mul$5$b = op_s$7;
        end
        if ((lane$39 == 5) & act$39) begin
            mul$5$a = ddx$3;
            mul$5$b = op_q$3;
        end
        if ((lane$40 == 5) & act$40) begin
            mul$5$a = ddx$0;
            mul$5$b = op_s$8;
        end
        if ((lane$41 == 5) & act$41) begin
            mul$5$a = ddy$0;
            mul$5$b = op_s$9;
        end
        if ((lane$42 == 5) & act$42) begin
            mul$5$a = ddx$0;
            mul$5$b = op_q$4;
        end
        if ((lane$43 == 5) & act$43) begin
            mul$5$a = ddx$1;
            mul$5$b = op_s$10;
        end
        if ((lane$44 == 5) & act$44) begin
            mul$5$a = ddy$1;
            mul$5$b = op_s$11;
        end
        if ((lane$45 == 5) & act$45) begin
            mul$5$a = ddx$1;
            mul$5$b = op_q$5;
        end
        if ((lane$46 == 5) & act$46) begin
            mul$5$a = ddx$2;
            mul$5$b = op_s$12;
        end
        if ((lane$47 == 5) & act$47) begin
            mul$5$a = ddy$2;
            mul$5$b = op_s$13;
        end
        if ((lane$48 == 5) & act$48) begin
            mul$5$a = ddx$2;
            mul$5$b = op_q$6;
        end
        if ((lane$49 == 5) & act$49) begin
            mul$5$a = ddx$3;
            mul$5$b = op_s$14;
        end
        if ((lane$50 == 5) & act$50) begin
            mul$5$a = ddy$3;
            mul$5$b = op_s$15;
        end
        if ((lane$51 == 5) & act$51) begin
            mul$5$a = ddx$3;
            mul$5$b = op_q$7;
        end
        if ((lane$52 == 5) & act$52) begin
            mul$5$a = ddx$0;
            mul$5$b = op_s$16;
        end
        if ((lane$53 == 5) & act$53) begin
            mul$5$a = ddy$0;
            mul$5$b = op_s$17;
        end
        if ((lane$54 == 5) & act$54) begin
            mul$5$a = ddx$0;
            mul$5$b = op_q$8;
        end
        if ((lane$55 == 5) & act$55) begin
            mul$5$a = ddx$1;
            mul$5$b = op_s$18;
        end
        if ((lane$56 == 5) & act$56) begin
            mul$5$a = ddy$1;
            mul$5$b = op_s$19;
        end
        if ((lane$57 == 5) & act$57) begin
            mul$5$a = ddx$1;
            mul$5$b = op_q$9;
        end
        if ((lane$58 == 5) & act$58) begin
            mul$5$a = ddx$2;
            mul$5$b = op_s$20;
        end
        if ((lane$59 == 5) & act$59) begin
            mul$5$a = ddy$2;
            mul$5$b = op_s$21;
        end
        if ((lane$60 == 5) & act$60) begin
            mul$5$a = ddx$2;
            mul$5$b = op_q$10;
        end
        if ((lane$61 == 5) & act$61) begin
            mul$5$a = ddx$3;
            mul$5$b = op_s$22;
        end
        if ((lane$62 == 5) & act$62) begin
            mul$5$a = ddy$3;
            mul$5$b = op_s$23;
        end
        if ((lane$63 == 5) & act$63) begin
            mul$5$a = ddx$3;
            mul$5$b = op_q$11;
        end
        if ((lane$28 == 5) & add$28) begin
            ps$0 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$29 == 5) & add$29) begin
            ps$1 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$30 == 5) & add$30) begin
            ps$2 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$31 == 5) & add$31) begin
            ps$3 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$32 == 5) & add$32) begin
            ps$4 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$33 == 5) & add$33) begin
            ps$5 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$34 == 5) & add$34) begin
            ps$6 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$35 == 5) & add$35) begin
            ps$7 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$36 == 5) & add$36) begin
            ps$8 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$37 == 5) & add$37) begin
            ps$9 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$38 == 5) & add$38) begin
            ps$10 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$39 == 5) & add$39) begin
            ps$11 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$40 == 5) & add$40) begin
            ps$12 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$41 == 5) & add$41) begin
            ps$13 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$42 == 5) & add$42) begin
            ps$14 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$43 == 5) & add$43) begin
            ps$15 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$44 == 5) & add$44) begin
            ps$16 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$45 == 5) & add$45) begin
            ps$17 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$46 == 5) & add$46) begin
            ps$18 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$47 == 5) & add$47) begin
            ps$19 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$48 == 5) & add$48) begin
            ps$20 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$49 == 5) & add$49) begin
            ps$21 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$50 == 5) & add$50) begin
            ps$22 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$51 == 5) & add$51) begin
            ps$23 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$52 == 5) & add$52) begin
            ps$24 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$53 == 5) & add$53) begin
            ps$25 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$54 == 5) & add$54) begin
            ps$26 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$55 == 5) & add$55) begin
            ps$27 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$56 == 5) & add$56) begin
            ps$28 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$57 == 5) & add$57) begin
            ps$29 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$58 == 5) & add$58) begin
            ps$30 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$59 == 5) & add$59) begin
            ps$31 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$60 == 5) & add$60) begin
            ps$32 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$61 == 5) & add$61) begin
            ps$33 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$62 == 5) & add$62) begin
            ps$34 = mul$5$p[(32'h0)+:(40)];
        end
        if ((lane$63 == 5) & add$63) begin
            ps$35 = mul$5$p[(32'h0)+:(40)];
        end
        mul$6$en = run;
        if ((lane$0 == 6) & act$0) begin
            mul$6$a = g0$kdx$0[(32'h0)+:(57)];
            mul$6$b = g0$kdy$1[(32'h0)+:(19)];
        end
        if ((lane$1 == 6) & act$1) begin
            mul$6$a = g0$kdx$1[(32'h0)+:(57)];
            mul$6$b = g0$kdy$0[(32'h0)+:(19)];
        end
        if ((lane$0 == 6) & add$0) begin
            pa$0 = mul$6$p[(32'h0)+:(34)];
        end
        if ((lane$1 == 6) & add$1) begin
            pa$1 = mul$6$p[(32'h0)+:(34)];
        end
        if ((lane$2 == 6) & act$2) begin
            mul$6$a = g0$edy$0;
            mul$6$b = g0$xf$0;
        end
        if ((lane$3 == 6) & act$3) begin
            mul$6$a = g0$edx$0[(32'h0)+:(57)];
            mul$6$b = g0$toff$0;
        end
        if ((lane$4 == 6) & act$4) begin
            mul$6$a = g0$edy$1;
            mul$6$b = g0$xf$1;
        end
        if ((lane$5 == 6) & act$5) begin
            mul$6$a = g0$edx$1[(32'h0)+:(57)];
            mul$6$b = g0$toff$1;
        end
        if ((lane$6 == 6) & act$6) begin
            mul$6$a = g0$edy$2;
            mul$6$b = g0$xf$2;
        end
        if ((lane$7 == 6) & act$7) begin
            mul$6$a = g0$edx$2[(32'h0)+:(57)];
            mul$6$b = g0$toff$2;
        end
        if ((lane$2 == 6) & add$2) begin
            pn$0 = mul$6$p;
        end
        if ((lane$3 == 6) & add$3) begin
            pn$1 = mul$6$p;
        end
        if ((lane$4 == 6) & add$4) begin
            pn$2 = mul$6$p;
        end
        if ((lane$5 == 6) & add$5) begin
            pn$3 = mul$6$p;
        end
        if ((lane$6 == 6) & add$6) begin
            pn$4 = mul$6$p;
        end
        if ((lane$7 == 6) & add$7) begin
            pn$5 = mul$6$p;
        end
        if ((lane$8 == 6) & act$8) begin
            mul$6$a = mant_s$q;
            mul$6$b = op_e$0;
        end
        if ((lane$8 == 6) & add$8) begin
            pe$0 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$9 == 6) & act$9) begin
            mul$6$a = mant_s$q;
            mul$6$b = op_e$1;
        end
        if ((lane$9 == 6) & add$9) begin
            pe$1 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$10 == 6) & act$10) begin
            mul$6$a = mant_s$q;
            mul$6$b = op_e$2;
        end
        if ((lane$10 == 6) & add$10) begin
            pe$2 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$11 == 6) & act$11) begin
            mul$6$a = mant_s$q;
            mul$6$b = op_e$3;
        end
        if ((lane$11 == 6) & add$11) begin
            pe$3 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$12 == 6) & act$12) begin
            mul$6$a = p$3$q;
            mul$6$b = op_g$0;
        end
        if ((lane$13 == 6) & act$13) begin
            mul$6$a = p$2$q;
            mul$6$b = op_g$1;
        end
        if ((lane$14 == 6) & act$14) begin
            mul$6$a = p$0$q;
            mul$6$b = op_g$2;
        end
        if ((lane$15 == 6) & act$15) begin
            mul$6$a = p$1$q;
            mul$6$b = op_g$3;
        end
        if ((lane$16 == 6) & act$16) begin
            mul$6$a = p$3$q;
            mul$6$b = op_g$4;
        end
        if ((lane$17 == 6) & act$17) begin
            mul$6$a = p$2$q;
            mul$6$b = op_g$5;
        end
        if ((lane$18 == 6) & act$18) begin
            mul$6$a = p$0$q;
            mul$6$b = op_g$6;
        end
        if ((lane$19 == 6) & act$19) begin
            mul$6$a = p$1$q;
            mul$6$b = op_g$7;
        end
        if ((lane$20 == 6) & act$20) begin
            mul$6$a = p$3$q;
            mul$6$b = op_g$8;
        end
        if ((lane$21 == 6) & act$21) begin
            mul$6$a = p$2$q;
            mul$6$b = op_g$9;
        end
        if ((lane$22 == 6) & act$22) begin
            mul$6$a = p$0$q;
            mul$6$b = op_g$10;
        end
        if ((lane$23 == 6) & act$23) begin
            mul$6$a = p$1$q;
            mul$6$b = op_g$11;
        end
        if ((lane$24 == 6) & act$24) begin
            mul$6$a = p$3$q;
            mul$6$b = op_g$12;
        end
        if ((lane$25 == 6) & act$25) begin
            mul$6$a = p$2$q;
            mul$6$b = op_g$13;
        end
        if ((lane$26 == 6) & act$26) begin
            mul$6$a = p$0$q;
            mul$6$b = op_g$14;
        end
        if ((lane$27 == 6) & act$27) begin
            mul$6$a = p$1$q;
            mul$6$b = op_g$15;
        end
        if ((lane$12 == 6) & add$12) begin
            pg$0 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$13 == 6) & add$13) begin
            pg$1 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$14 == 6) & add$14) begin
            pg$2 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$15 == 6) & add$15) begin
            pg$3 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$16 == 6) & add$16) begin
            pg$4 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$17 == 6) & add$17) begin
            pg$5 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$18 == 6) & add$18) begin
            pg$6 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$19 == 6) & add$19) begin
            pg$7 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$20 == 6) & add$20) begin
            pg$8 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$21 == 6) & add$21) begin
            pg$9 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$22 == 6) & add$22) begin
            pg$10 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$23 == 6) & add$23) begin
            pg$11 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$24 == 6) & add$24) begin
            pg$12 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$25 == 6) & add$25) begin
            pg$13 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$26 == 6) & add$26) begin
            pg$14 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$27 == 6) & add$27) begin
            pg$15 = mul$6$p[(32'h0)+:(57)];
        end
        if ((lane$28 == 6) & act$28) begin
            mul$6$a = ddx$0;
            mul$6$b = op_s$0;
        end
        if ((lane$29 == 6) & act$29) begin
            mul$6$a = ddy$0;
            mul$6$b = op_s$1;
        end
        if ((lane$30 == 6) & act$30) begin
            mul$6$a = ddx$0;
            mul$6$b = op_q$0;
        end
        if ((lane$31 == 6) & act$31) begin
            mul$6$a = ddx$1;
            mul$6$b = op_s$2;
        end
        if ((lane$32 == 6) & act$32) begin
            mul$6$a = ddy$1;
            mul$6$b = op_s$3;
        end
        if ((lane$33 == 6) & act$33) begin
            mul$6$a = ddx$1;
            mul$6$b = op_q$1;
        end
        if ((lane$34 == 6) & act$34) begin
            mul$6$a = ddx$2;
            mul$6$b = op_s$4;
        end
        if ((lane$35 == 6) & act$35) begin
            mul$6$a = ddy$2;
            mul$6$b = op_s$5;
        end
        if ((lane$36 == 6) & act$36) begin
            mul$6$a = ddx$2;
            mul$6$b = op_q$2;
        end
        if ((lane$37 == 6) & act$37) begin
            mul$6$a = ddx$3;
            mul$6$b = op_s$6;
        end
        if ((lane$38 == 6) & act$38) begin
            mul$6$a = ddy$3;
            mul$6$b = op_s$7;
        end
        if ((lane$39 == 6) & act$39) begin
            mul$6$a = ddx$3;
            mul$6$b = op_q$3;
        end
        if ((lane$40 == 6) & act$40) begin
            mul$6$a = ddx$0;
            mul$6$b = op_s$8;
        end
        if ((lane$41 == 6) & act$41) begin
            mul$6$a = ddy$0;
            mul$6$b = op_s$9;
        end
        if ((lane$42 == 6) & act$42) begin
            mul$6$a = ddx$0;
            mul$6$b = op_q$4;
        end
        if ((lane$43 == 6) & act$43) begin
            mul$6$a = ddx$1;
            mul$6$b = op_s$10;
        end
        if ((lane$44 == 6) & act$44) begin
            mul$6$a = ddy$1;
            mul$6$b = op_s$11;
        end
        if ((lane$45 == 6) & act$45) begin
            mul$6$a = ddx$1;
            mul$6$b = op_q$5;
        end
        if ((lane$46 == 6) & act$46) begin
            mul$6$a = ddx$2;
            mul$6$b = op_s$12;
        end
        if ((lane$47 == 6) & act$47) begin
            mul$6$a = ddy$2;
            mul$6$b = op_s$13;
        end
        if ((lane$48 == 6) & act$48) begin
            mul$6$a = ddx$2;
            mul$6$b = op_q$6;
        end
        if ((lane$49 == 6) & act$49) begin
            mul$6$a = ddx$3;
            mul$6$b = op_s$14;
        end
        if ((lane$50 == 6) & act$50) begin
            mul$6$a = ddy$3;
            mul$6$b = op_s$15;
        end
        if ((lane$51 == 6) & act$51) begin
            mul$6$a = ddx$3;
            mul$6$b = op_q$7;
        end
        if ((lane$52 == 6) & act$52) begin
            mul$6$a = ddx$0;
            mul$6$b = op_s$16;
        end
        if ((lane$53 == 6) & act$53) begin
            mul$6$a = ddy$0;
            mul$6$b = op_s$17;
        end
        if ((lane$54 == 6) & act$54) begin
            mul$6$a = ddx$0;
            mul$6$b = op_q$8;
        end
        if ((lane$55 == 6) & act$55) begin
            mul$6$a = ddx$1;
            mul$6$b = op_s$18;
        end
        if ((lane$56 == 6) & act$56) begin
            mul$6$a = ddy$1;
            mul$6$b = op_s$19;
        end
        if ((lane$57 == 6) & act$57) begin
            mul$6$a = ddx$1;
            mul$6$b = op_q$9;
        end
        if ((lane$58 == 6) & act$58) begin
            mul$6$a = ddx$2;
            mul$6$b = op_s$20;
        end
        if ((lane$59 == 6) & act$59) begin
            mul$6$a = ddy$2;
            mul$6$b = op_s$21;
        end
        if ((lane$60 == 6) & act$60) begin
            mul$6$a = ddx$2;
            mul$6$b = op_q$10;
        end
        if ((lane$61 == 6) & act$61) begin
            mul$6$a = ddx$3;
            mul$6$b = op_s$22;
        end
        if ((lane$62 == 6) & act$62) begin
            mul$6$a = ddy$3;
            mul$6$b = op_s$23;
        end
        if ((lane$63 == 6) & act$63) begin
            mul$6$a = ddx$3;
            mul$6$b = op_q$11;
        end
        if ((lane$28 == 6) & add$28) begin
            ps$0 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$29 == 6) & add$29) begin
            ps$1 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$30 == 6) & add$30) begin
            ps$2 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$31 == 6) & add$31) begin
            ps$3 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$32 == 6) & add$32) begin
            ps$4 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$33 == 6) & add$33) begin
            ps$5 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$34 == 6) & add$34) begin
            ps$6 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$35 == 6) & add$35) begin
            ps$7 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$36 == 6) & add$36) begin
            ps$8 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$37 == 6) & add$37) begin
            ps$9 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$38 == 6) & add$38) begin
            ps$10 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$39 == 6) & add$39) begin
            ps$11 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$40 == 6) & add$40) begin
            ps$12 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$41 == 6) & add$41) begin
            ps$13 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$42 == 6) & add$42) begin
            ps$14 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$43 == 6) & add$43) begin
            ps$15 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$44 == 6) & add$44) begin
            ps$16 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$45 == 6) & add$45) begin
            ps$17 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$46 == 6) & add$46) begin
            ps$18 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$47 == 6) & add$47) begin
            ps$19 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$48 == 6) & add$48) begin
            ps$20 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$49 == 6) & add$49) begin
            ps$21 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$50 == 6) & add$50) begin
            ps$22 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$51 == 6) & add$51) begin
            ps$23 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$52 == 6) & add$52) begin
            ps$24 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$53 == 6) & add$53) begin
            ps$25 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$54 == 6) & add$54) begin
            ps$26 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$55 == 6) & add$55) begin
            ps$27 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$56 == 6) & add$56) begin
            ps$28 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$57 == 6) & add$57) begin
            ps$29 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$58 == 6) & add$58) begin
            ps$30 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$59 == 6) & add$59) begin
            ps$31 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$60 == 6) & add$60) begin
            ps$32 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$61 == 6) & add$61) begin
            ps$33 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$62 == 6) & add$62) begin
            ps$34 = mul$6$p[(32'h0)+:(40)];
        end
        if ((lane$63 == 6) & add$63) begin
            ps$35 = mul$6$p[(32'h0)+:(40)];
        end
        area_base = area$q;
        if (add$0) begin
            area_base = 32'h0;
        end
        num_base$0 = num$0$q;
        if (add$2) begin
            num_base$0 = 32'h0;
        end
        num_base$1 = num$1$q;
        if (add$4) begin
            num_base$1 = 32'h0;
        end
        num_base$2 = num$2$q;
        if (add$6) begin
            num_base$2 = 32'h0;
        end
        shr$0 = pe$0 >> rsh$q;
        if (pe$0[p_msb]) begin
            shr$0 = (pe$0 >> rsh$q) | ~(ones >> rsh$q);
        end
        shr$1 = pe$1 >> rsh$q;
        if (pe$1[p_msb]) begin
            shr$1 = (pe$1 >> rsh$q) | ~(ones >> rsh$q);
        end
        shr$2 = pe$2 >> rsh$q;
        if (pe$2[p_msb]) begin
            shr$2 = (pe$2 >> rsh$q) | ~(ones >> rsh$q);
        end
        shr$3 = pe$3 >> rsh$q;
        if (pe$3[p_msb]) begin
            shr$3 = (pe$3 >> rsh$q) | ~(ones >> rsh$q);
        end
        gx_base$0 = gx$0$q;
        if (add$12) begin
            gx_base$0 = 32'h0;
        end
        gy_base$0 = gy$0$q;
        if (add$14) begin
            gy_base$0 = 32'h0;
        end
        gx_base$1 = gx$1$q;
        if (add$16) begin
            gx_base$1 = 32'h0;
        end
        gy_base$1 = gy$1$q;
        if (add$18) begin
            gy_base$1 = 32'h0;
        end
        gx_base$2 = gx$2$q;
        if (add$20) begin
            gx_base$2 = 32'h0;
        end
        gy_base$2 = gy$2$q;
        if (add$22) begin
            gy_base$2 = 32'h0;
        end
        gx_base$3 = gx$3$q;
        if (add$24) begin
            gx_base$3 = 32'h0;
        end
        gy_base$3 = gy$3$q;
        if (add$26) begin
            gy_base$3 = 32'h0;
        end
        plane_base$0 = plane$0$q;
        if (add$28) begin
            plane_base$0 = 32'h0;
        end
        plane_base$1 = plane$1$q;
        if (add$31) begin
            plane_base$1 = 32'h0;
        end
        plane_base$2 = plane$2$q;
        if (add$34) begin
            plane_base$2 = 32'h0;
        end
        plane_base$3 = plane$3$q;
        if (add$37) begin
            plane_base$3 = 32'h0;
        end
        plane_base$4 = plane$4$q;
        if (add$40) begin
            plane_base$4 = 32'h0;
        end
        plane_base$5 = plane$5$q;
        if (add$43) begin
            plane_base$5 = 32'h0;
        end
        plane_base$6 = plane$6$q;
        if (add$46) begin
            plane_base$6 = 32'h0;
        end
        plane_base$7 = plane$7$q;
        if (add$49) begin
            plane_base$7 = 32'h0;
        end
        plane_base$8 = plane$8$q;
        if (add$52) begin
            plane_base$8 = 32'h0;
        end
        plane_base$9 = plane$9$q;
        if (add$55) begin
            plane_base$9 = 32'h0;
        end
        plane_base$10 = plane$10$q;
        if (add$58) begin
            plane_base$10 = 32'h0;
        end
        plane_base$11 = plane$11$q;
        if (add$61) begin
            plane_base$11 = 32'h0;
        end
        if (run) begin
            area$d = area_base + pa$0 - pa$1;
            num$0$d = num_base$0 + pn$0 + pn$1;
            num$1$d = num_base$1 + pn$2 + pn$3;
            num$2$d = num_base$2 + pn$4 + pn$5;
            if (add$8) begin
                p$0$d = shr$0;
                if (left$q) begin
                    p$0$d = pe$0;
                end
            end
            if (add$9) begin
                p$1$d = shr$1;
                if (left$q) begin
                    p$1$d = pe$1;
                end
            end
            if (add$10) begin
                p$2$d = shr$2;
                if (left$q) begin
                    p$2$d = pe$2;
                end
            end
            if (add$11) begin
                p$3$d = shr$3;
                if (left$q) begin
                    p$3$d = pe$3;
                end
            end
            gx$0$d = gx_base$0 + pg$0 - pg$1;
            gy$0$d = gy_base$0 + pg$2 - pg$3;
            gx$1$d = gx_base$1 + pg$4 - pg$5;
            gy$1$d = gy_base$1 + pg$6 - pg$7;
            gx$2$d = gx_base$2 + pg$8 - pg$9;
            gy$2$d = gy_base$2 + pg$10 - pg$11;
            gx$3$d = gx_base$3 + pg$12 - pg$13;
            gy$3$d = gy_base$3 + pg$14 - pg$15;
            plane$0$d = plane_base$0 + ps$0 + ps$1;
            if (add$30) begin
                inc0$0$d = ddy$0[(32'h0)+:(40)] + ps$2;
                inc1$0$d = ddy$0[(32'h0)+:(40)] + ps$2 + ddx$0[(32'h0)+:(40)];
                ddx_o$0$d = ddx$0[(32'h0)+:(40)];
            end
            plane$1$d = plane_base$1 + ps$3 + ps$4;
            if (add$33) begin
                inc0$1$d = ddy$1[(32'h0)+:(40)] + ps$5;
                inc1$1$d = ddy$1[(32'h0)+:(40)] + ps$5 + ddx$1[(32'h0)+:(40)];
                ddx_o$1$d = ddx$1[(32'h0)+:(40)];
            end
            plane$2$d = plane_base$2 + ps$6 + ps$7;
            if (add$36) begin
                inc0$2$d = ddy$2[(32'h0)+:(40)] + ps$8;
                inc1$2$d = ddy$2[(32'h0)+:(40)] + ps$8 + ddx$2[(32'h0)+:(40)];
                ddx_o$2$d = ddx$2[(32'h0)+:(40)];
            end
            plane$3$d = plane_base$3 + ps$9 + ps$10;
            if (add$39) begin
                inc0$3$d = ddy$3[(32'h0)+:(40)] + ps$11;
                inc1$3$d = ddy$3[(32'h0)+:(40)] + ps$11 + ddx$3[(32'h0)+:(40)];
                ddx_o$3$d = ddx$3[(32'h0)+:(40)];
            end
            plane$4$d = plane_base$4 + ps$12 + ps$13;
            if (add$42) begin
                inc0$4$d = ddy$0[(32'h0)+:(40)] + ps$14;
                inc1$4$d = ddy$0[(32'h0)+:(40)] + ps$14 + ddx$0[(32'h0)+:(40)];
                ddx_o$0$d = ddx$0[(32'h0)+:(40)];
            end
            plane$5$d = plane_base$5 + ps$15 + ps$16;
            if (add$45) begin
                inc0$5$d = ddy$1[(32'h0)+:(40)] + ps$17;
                inc1$5$d = ddy$1[(32'h0)+:(40)] + ps$17 + ddx$1[(32'h0)+:(40)];
                ddx_o$1$d = ddx$1[(32'h0)+:(40)];
            end
            plane$6$d = plane_base$6 + ps$18 + ps$19;
            if (add$48) begin
                inc0$6$d = ddy$2[(32'h0)+:(40)] + ps$20;
                inc1$6$d = ddy$2[(32'h0)+:(40)] + ps$20 + ddx$2[(32'h0)+:(40)];
                ddx_o$2$d = ddx$2[(32'h0)+:(40)];
            end
            plane$7$d = plane_base$7 + ps$21 + ps$22;
            if (add$51) begin
                inc0$7$d = ddy$3[(32'h0)+:(40)] + ps$23;
                inc1$7$d = ddy$3[(32'h0)+:(40)] + ps$23 + ddx$3[(32'h0)+:(40)];
                ddx_o$3$d = ddx$3[(32'h0)+:(40)];
            end
            plane$8$d = plane_base$8 + ps$24 + ps$25;
            if (add$54) begin
                inc0$8$d = ddy$0[(32'h0)+:(40)] + ps$26;
                inc1$8$d = ddy$0[(32'h0)+:(40)] + ps$26 + ddx$0[(32'h0)+:(40)];
                ddx_o$0$d = ddx$0[(32'h0)+:(40)];
            end
            plane$9$d = plane_base$9 + ps$27 + ps$28;
            if (add$57) begin
                inc0$9$d = ddy$1[(32'h0)+:(40)] + ps$29;
                inc1$9$d = ddy$1[(32'h0)+:(40)] + ps$29 + ddx$1[(32'h0)+:(40)];
                ddx_o$1$d = ddx$1[(32'h0)+:(40)];
            end
            plane$10$d = plane_base$10 + ps$30 + ps$31;
            if (add$60) begin
                inc0$10$d = ddy$2[(32'h0)+:(40)] + ps$32;
                inc1$10$d = ddy$2[(32'h0)+:(40)] + ps$32 + ddx$2[(32'h0)+:(40)];
                ddx_o$2$d = ddx$2[(32'h0)+:(40)];
            end
            plane$11$d = plane_base$11 + ps$33 + ps$34;
            if (add$63) begin
                inc0$11$d = ddy$3[(32'h0)+:(40)] + ps$35;
                inc1$11$d = ddy$3[(32'h0)+:(40)] + ps$35 + ddx$3[(32'h0)+:(40)];
                ddx_o$3$d = ddx$3[(32'h0)+:(40)];
            end
        end
        if (at_handover) begin
            plane$0$d = (plane$0$q >> frac) + (attr0$0 << bsh$0);
        end
        if (at_handover) begin
            plane$1$d = (plane$1$q >> frac) + (attr0$1 << bsh$1);
        end
        if (at_handover) begin
            plane$2$d = (plane$2$q >> frac) + (attr0$2 << bsh$2);
        end
        if (at_handover) begin
            plane$3$d = (plane$3$q >> frac) + (attr0$3 << bsh$3);
        end
        if (at_handover) begin
            plane$4$d = (plane$4$q >> frac) + (attr0$0 << bsh$0);
        end
        if (at_handover) begin
            plane$5$d = (plane$5$q >> frac) + (attr0$1 << bsh$1);
        end
        if (at_handover) begin
            plane$6$d = (plane$6$q >> frac) + (attr0$2 << bsh$2);
        end
        if (at_handover) begin
            plane$7$d = (plane$7$q >> frac) + (attr0$3 << bsh$3);
        end
        if (at_handover) begin
            plane$8$d = (plane$8$q >> frac) + (attr0$0 << bsh$0);
        end
        if (at_handover) begin
            plane$9$d = (plane$9$q >> frac) + (attr0$1 << bsh$1);
        end
        if (at_handover) begin
            plane$10$d = (plane$10$q >> frac) + (attr0$2 << bsh$2);
        end
        if (at_handover) begin
            plane$11$d = (plane$11$q >> frac) + (attr0$3 << bsh$3);
        end
        if (at_handover & (view_handover == 32'h0)) begin
            o_walk$d = g0$up;
            o_maj_left$d = maj_left$0;
            o_j$0$d = g0$cy$0[(frac)+:(13)];
            o_count$0$d = g0$count$0;
            o_d$0$d = g0$ed16$0[(32'h0)+:(21)];
            o_j$1$d = g0$cy$1[(frac)+:(13)];
            o_count$1$d = g0$count$1;
            o_d$1$d = g0$ed16$1[(32'h0)+:(21)];
            o_j$2$d = g0$cy$2[(frac)+:(13)];
            o_count$2$d = g0$count$2;
            o_d$2$d = g0$ed16$2[(32'h0)+:(21)];
        end
        if (at_handover & (view_handover == 32'h1)) begin
            o_walk$d = g1$up;
            o_maj_left$d = maj_left$1;
            o_j$0$d = g1$cy$0[(frac)+:(13)];
            o_count$0$d = g1$count$0;
            o_d$0$d = g1$ed16$0[(32'h0)+:(21)];
            o_j$1$d = g1$cy$1[(frac)+:(13)];
            o_count$1$d = g1$count$1;
            o_d$1$d = g1$ed16$1[(32'h0)+:(21)];
            o_j$2$d = g1$cy$2[(frac)+:(13)];
            o_count$2$d = g1$count$2;
            o_d$2$d = g1$ed16$2[(32'h0)+:(21)];
        end
        if (at_handover & (view_handover == 32'h2)) begin
            o_walk$d = g2$up;
            o_maj_left$d = maj_left$2;
            o_j$0$d = g2$cy$0[(frac)+:(13)];
            o_count$0$d = g2$count$0;
            o_d$0$d = g2$ed16$0[(32'h0)+:(21)];
            o_j$1$d = g2$cy$1[(frac)+:(13)];
            o_count$1$d = g2$count$1;
            o_d$1$d = g2$ed16$1[(32'h0)+:(21)];
            o_j$2$d = g2$cy$2[(frac)+:(13)];
            o_count$2$d = g2$count$2;
            o_d$2$d = g2$ed16$2[(32'h0)+:(21)];
        end
        if (at_handover & (view_handover == 32'h3)) begin
            o_walk$d = g3$up;
            o_maj_left$d = maj_left$3;
            o_j$0$d = g3$cy$0[(frac)+:(13)];
            o_count$0$d = g3$count$0;
            o_d$0$d = g3$ed16$0[(32'h0)+:(21)];
            o_j$1$d = g3$cy$1[(frac)+:(13)];
            o_count$1$d = g3$count$1;
            o_d$1$d = g3$ed16$1[(32'h0)+:(21)];
            o_j$2$d = g3$cy$2[(frac)+:(13)];
            o_count$2$d = g3$count$2;
            o_d$2$d = g3$ed16$2[(32'h0)+:(21)];
        end
        if (at_handover & (view_handover == 32'h4)) begin
            o_walk$d = g4$up;
            o_maj_left$d = maj_left$4;
            o_j$0$d = g4$cy$0[(frac)+:(13)];
            o_count$0$d = g4$count$0;
            o_d$0$d = g4$ed16$0[(32'h0)+:(21)];
            o_j$1$d = g4$cy$1[(frac)+:(13)];
            o_count$1$d = g4$count$1;
            o_d$1$d = g4$ed16$1[(32'h0)+:(21)];
            o_j$2$d = g4$cy$2[(frac)+:(13)];
            o_count$2$d = g4$count$2;
            o_d$2$d = g4$ed16$2[(32'h0)+:(21)];
        end
        if (at_handover & (view_handover == 32'h5)) begin
            o_walk$d = g5$up;
            o_maj_left$d = maj_left$5;
            o_j$0$d = g5$cy$0[(frac)+:(13)];
            o_count$0$d = g5$count$0;
            o_d$0$d = g5$ed16$0[(32'h0)+:(21)];
            o_j$1$d = g5$cy$1[(frac)+:(13)];
            o_count$1$d = g5$count$1;
            o_d$1$d = g5$ed16$1[(32'h0)+:(21)];
            o_j$2$d = g5$cy$2[(frac)+:(13)];
            o_count$2$d = g5$count$2;
            o_d$2$d = g5$ed16$2[(32'h0)+:(21)];
        end
        out$walk = o_walk$q;
        out$maj_left = o_maj_left$q;
        out$maj_j = o_j$0$q;
        out$maj_count = o_count$0$q;
        out$maj_d = o_d$0$q;
        out$short0_j = o_j$1$q;
        out$short0_count = o_count$1$q;
        out$short0_d = o_d$1$q;
        out$short1_j = o_j$2$q;
        out$short1_count = o_count$2$q;
        out$short1_d = o_d$2$q;
        recip_mant = mant$5$q;
        recip_exp = exp$5$q;
        out$maj_x = x$15$q[(32'h0)+:(13)];
        out$maj_r = r$15$q;
        out$maj_q = q$15$q[(32'h0)+:(17)];
        out$maj_rho = rho$15$q;
        out$short0_x = x$16$q[(32'h0)+:(13)];
        out$short0_r = r$16$q;
        out$short0_q = q$16$q[(32'h0)+:(17)];
        out$short0_rho = rho$16$q;
        out$short1_x = x$17$q[(32'h0)+:(13)];
        out$short1_r = r$17$q;
        out$short1_q = q$17$q[(32'h0)+:(17)];
        out$short1_rho = rho$17$q;
        out$maj_at_z = plane$0$q[(32'h0)+:(36)];
        out$maj_at_c0 = plane$1$q[(32'h0)+:(32)];
        out$maj_at_c1 = plane$2$q[(32'h0)+:(32)];
        out$maj_at_c2 = plane$3$q[(32'h0)+:(32)];
        out$maj_inc0_z = inc0$0$q[(32'h0)+:(40)];
        out$maj_inc0_c0 = inc0$1$q[(32'h0)+:(36)];
        out$maj_inc0_c1 = inc0$2$q[(32'h0)+:(36)];
        out$maj_inc0_c2 = inc0$3$q[(32'h0)+:(36)];
        out$maj_inc1_z = inc1$0$q[(32'h0)+:(40)];
        out$maj_inc1_c0 = inc1$1$q[(32'h0)+:(36)];
        out$maj_inc1_c1 = inc1$2$q[(32'h0)+:(36)];
        out$maj_inc1_c2 = inc1$3$q[(32'h0)+:(36)];
        out$short0_at_z = plane$4$q[(32'h0)+:(36)];
        out$short0_at_c0 = plane$5$q[(32'h0)+:(32)];
        out$short0_at_c1 = plane$6$q[(32'h0)+:(32)];
        out$short0_at_c2 = plane$7$q[(32'h0)+:(32)];
        out$short0_inc0_z = inc0$4$q[(32'h0)+:(40)];
        out$short0_inc0_c0 = inc0$5$q[(32'h0)+:(36)];
        out$short0_inc0_c1 = inc0$6$q[(32'h0)+:(36)];
        out$short0_inc0_c2 = inc0$7$q[(32'h0)+:(36)];
        out$short0_inc1_z = inc1$4$q[(32'h0)+:(40)];
        out$short0_inc1_c0 = inc1$5$q[(32'h0)+:(36)];
        out$short0_inc1_c1 = inc1$6$q[(32'h0)+:(36)];
        out$short0_inc1_c2 = inc1$7$q[(32'h0)+:(36)];
        out$short1_at_z = plane$8$q[(32'h0)+:(36)];
        out$short1_at_c0 = plane$9$q[(32'h0)+:(32)];
        out$short1_at_c1 = plane$10$q[(32'h0)+:(32)];
        out$short1_at_c2 = plane$11$q[(32'h0)+:(32)];
        out$short1_inc0_z = inc0$8$q[(32'h0)+:(40)];
        out$short1_inc0_c0 = inc0$9$q[(32'h0)+:(36)];
        out$short1_inc0_c1 = inc0$10$q[(32'h0)+:(36)];
        out$short1_inc0_c2 = inc0$11$q[(32'h0)+:(36)];
        out$short1_inc1_z = inc1$8$q[(32'h0)+:(40)];
        out$short1_inc1_c0 = inc1$9$q[(32'h0)+:(36)];
        out$short1_inc1_c1 = inc1$10$q[(32'h0)+:(36)];
        out$short1_inc1_c2 = inc1$11$q[(32'h0)+:(36)];
        out$ddx_z = ddx_o$0$q[(32'h0)+:(40)];
        out$ddx_c0 = ddx_o$1$q[(32'h0)+:(36)];
        out$ddx_c1 = ddx_o$2$q[(32'h0)+:(36)];
        out$ddx_c2 = ddx_o$3$q[(32'h0)+:(36)];
    end
    
endmodule // raster_top$fragments$core$triangle_setup


module raster_top$fragments$core$triangle_setup$area(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$area


module raster_top$fragments$core$triangle_setup$busy_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$busy_r


module raster_top$fragments$core$triangle_setup$ddx_o$0(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$ddx_o$0


module raster_top$fragments$core$triangle_setup$ddx_o$1(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$ddx_o$1


module raster_top$fragments$core$triangle_setup$ddx_o$2(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$ddx_o$2


module raster_top$fragments$core$triangle_setup$ddx_o$3(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$ddx_o$3


module raster_top$fragments$core$triangle_setup$div(clock,inp_valid,inp_ready,hold,inp_n,inp_d,out_valid,out_ready,out_q,out_r);
    
    // Module arguments
    input wire  clock;
    input wire  inp_valid;
    output reg  inp_ready;
    input wire  hold;
    input wire  [57:0] inp_n;
    input wire  [33:0] inp_d;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [25:0] out_q;
    output reg  [33:0] out_r;
    
    // Constant declarations
    localparam  n_msb = 8'h39;
    localparam  qm = 8'h19;
    localparam  q_sign = 26'h2000000;
    
    // Stub signals
    reg  stages$0$clock;
    reg  stages$0$enable;
    reg  stages$0$valid_in;
    reg  [33:0] stages$0$p_in;
    reg  [24:0] stages$0$x_in;
    reg  [33:0] stages$0$d_in;
    reg  stages$0$neg_in;
    wire  stages$0$valid;
    wire  [33:0] stages$0$p;
    wire  [24:0] stages$0$x;
    wire  [33:0] stages$0$d;
    wire  stages$0$neg;
    reg  stages$1$clock;
    reg  stages$1$enable;
    reg  stages$1$valid_in;
    reg  [33:0] stages$1$p_in;
    reg  [24:0] stages$1$x_in;
    reg  [33:0] stages$1$d_in;
    reg  stages$1$neg_in;
    wire  stages$1$valid;
    wire  [33:0] stages$1$p;
    wire  [24:0] stages$1$x;
    wire  [33:0] stages$1$d;
    wire  stages$1$neg;
    reg  stages$2$clock;
    reg  stages$2$enable;
    reg  stages$2$valid_in;
    reg  [33:0] stages$2$p_in;
    reg  [24:0] stages$2$x_in;
    reg  [33:0] stages$2$d_in;
    reg  stages$2$neg_in;
    wire  stages$2$valid;
    wire  [33:0] stages$2$p;
    wire  [24:0] stages$2$x;
    wire  [33:0] stages$2$d;
    wire  stages$2$neg;
    reg  stages$3$clock;
    reg  stages$3$enable;
    reg  stages$3$valid_in;
    reg  [33:0] stages$3$p_in;
    reg  [24:0] stages$3$x_in;
    reg  [33:0] stages$3$d_in;
    reg  stages$3$neg_in;
    wire  stages$3$valid;
    wire  [33:0] stages$3$p;
    wire  [24:0] stages$3$x;
    wire  [33:0] stages$3$d;
    wire  stages$3$neg;
    reg  stages$4$clock;
    reg  stages$4$enable;
    reg  stages$4$valid_in;
    reg  [33:0] stages$4$p_in;
    reg  [24:0] stages$4$x_in;
    reg  [33:0] stages$4$d_in;
    reg  stages$4$neg_in;
    wire  stages$4$valid;
    wire  [33:0] stages$4$p;
    wire  [24:0] stages$4$x;
    wire  [33:0] stages$4$d;
    wire  stages$4$neg;
    reg  stages$5$clock;
    reg  stages$5$enable;
    reg  stages$5$valid_in;
    reg  [33:0] stages$5$p_in;
    reg  [24:0] stages$5$x_in;
    reg  [33:0] stages$5$d_in;
    reg  stages$5$neg_in;
    wire  stages$5$valid;
    wire  [33:0] stages$5$p;
    wire  [24:0] stages$5$x;
    wire  [33:0] stages$5$d;
    wire  stages$5$neg;
    reg  stages$6$clock;
    reg  stages$6$enable;
    reg  stages$6$valid_in;
    reg  [33:0] stages$6$p_in;
    reg  [24:0] stages$6$x_in;
    reg  [33:0] stages$6$d_in;
    reg  stages$6$neg_in;
    wire  stages$6$valid;
    wire  [33:0] stages$6$p;
    wire  [24:0] stages$6$x;
    wire  [33:0] stages$6$d;
    wire  stages$6$neg;
    reg  stages$7$clock;
    reg  stages$7$enable;
    reg  stages$7$valid_in;
    reg  [33:0] stages$7$p_in;
    reg  [24:0] stages$7$x_in;
    reg  [33:0] stages$7$d_in;
    reg  stages$7$neg_in;
    wire  stages$7$valid;
    wire  [33:0] stages$7$p;
    wire  [24:0] stages$7$x;
    wire  [33:0] stages$7$d;
    wire  stages$7$neg;
    reg  stages$8$clock;
    reg  stages$8$enable;
    reg  stages$8$valid_in;
    reg  [33:0] stages$8$p_in;
    reg  [24:0] stages$8$x_in;
    reg  [33:0] stages$8$d_in;
    reg  stages$8$neg_in;
    wire  stages$8$valid;
    wire  [33:0] stages$8$p;
    wire  [24:0] stages$8$x;
    wire  [33:0] stages$8$d;
    wire  stages$8$neg;
    reg  stages$9$clock;
    reg  stages$9$enable;
    reg  stages$9$valid_in;
    reg  [33:0] stages$9$p_in;
    reg  [24:0] stages$9$x_in;
    reg  [33:0] stages$9$d_in;
    reg  stages$9$neg_in;
    wire  stages$9$valid;
    wire  [33:0] stages$9$p;
    wire  [24:0] stages$9$x;
    wire  [33:0] stages$9$d;
    wire  stages$9$neg;
    reg  stages$10$clock;
    reg  stages$10$enable;
    reg  stages$10$valid_in;
    reg  [33:0] stages$10$p_in;
    reg  [24:0] stages$10$x_in;
    reg  [33:0] stages$10$d_in;
    reg  stages$10$neg_in;
    wire  stages$10$valid;
    wire  [33:0] stages$10$p;
    wire  [24:0] stages$10$x;
    wire  [33:0] stages$10$d;
    wire  stages$10$neg;
    reg  stages$11$clock;
    reg  stages$11$enable;
    reg  stages$11$valid_in;
    reg  [33:0] stages$11$p_in;
    reg  [24:0] stages$11$x_in;
    reg  [33:0] stages$11$d_in;
    reg  stages$11$neg_in;
    wire  stages$11$valid;
    wire  [33:0] stages$11$p;
    wire  [24:0] stages$11$x;
    wire  [33:0] stages$11$d;
    wire  stages$11$neg;
    reg  stages$12$clock;
    reg  stages$12$enable;
    reg  stages$12$valid_in;
    reg  [33:0] stages$12$p_in;
    reg  [24:0] stages$12$x_in;
    reg  [33:0] stages$12$d_in;
    reg  stages$12$neg_in;
    wire  stages$12$valid;
    wire  [33:0] stages$12$p;
    wire  [24:0] stages$12$x;
    wire  [33:0] stages$12$d;
    wire  stages$12$neg;
    reg  stages$13$clock;
    reg  stages$13$enable;
    reg  stages$13$valid_in;
    reg  [33:0] stages$13$p_in;
    reg  [24:0] stages$13$x_in;
    reg  [33:0] stages$13$d_in;
    reg  stages$13$neg_in;
    wire  stages$13$valid;
    wire  [33:0] stages$13$p;
    wire  [24:0] stages$13$x;
    wire  [33:0] stages$13$d;
    wire  stages$13$neg;
    reg  stages$14$clock;
    reg  stages$14$enable;
    reg  stages$14$valid_in;
    reg  [33:0] stages$14$p_in;
    reg  [24:0] stages$14$x_in;
    reg  [33:0] stages$14$d_in;
    reg  stages$14$neg_in;
    wire  stages$14$valid;
    wire  [33:0] stages$14$p;
    wire  [24:0] stages$14$x;
    wire  [33:0] stages$14$d;
    wire  stages$14$neg;
    reg  stages$15$clock;
    reg  stages$15$enable;
    reg  stages$15$valid_in;
    reg  [33:0] stages$15$p_in;
    reg  [24:0] stages$15$x_in;
    reg  [33:0] stages$15$d_in;
    reg  stages$15$neg_in;
    wire  stages$15$valid;
    wire  [33:0] stages$15$p;
    wire  [24:0] stages$15$x;
    wire  [33:0] stages$15$d;
    wire  stages$15$neg;
    reg  stages$16$clock;
    reg  stages$16$enable;
    reg  stages$16$valid_in;
    reg  [33:0] stages$16$p_in;
    reg  [24:0] stages$16$x_in;
    reg  [33:0] stages$16$d_in;
    reg  stages$16$neg_in;
    wire  stages$16$valid;
    wire  [33:0] stages$16$p;
    wire  [24:0] stages$16$x;
    wire  [33:0] stages$16$d;
    wire  stages$16$neg;
    reg  stages$17$clock;
    reg  stages$17$enable;
    reg  stages$17$valid_in;
    reg  [33:0] stages$17$p_in;
    reg  [24:0] stages$17$x_in;
    reg  [33:0] stages$17$d_in;
    reg  stages$17$neg_in;
    wire  stages$17$valid;
    wire  [33:0] stages$17$p;
    wire  [24:0] stages$17$x;
    wire  [33:0] stages$17$d;
    wire  stages$17$neg;
    reg  stages$18$clock;
    reg  stages$18$enable;
    reg  stages$18$valid_in;
    reg  [33:0] stages$18$p_in;
    reg  [24:0] stages$18$x_in;
    reg  [33:0] stages$18$d_in;
    reg  stages$18$neg_in;
    wire  stages$18$valid;
    wire  [33:0] stages$18$p;
    wire  [24:0] stages$18$x;
    wire  [33:0] stages$18$d;
    wire  stages$18$neg;
    reg  stages$19$clock;
    reg  stages$19$enable;
    reg  stages$19$valid_in;
    reg  [33:0] stages$19$p_in;
    reg  [24:0] stages$19$x_in;
    reg  [33:0] stages$19$d_in;
    reg  stages$19$neg_in;
    wire  stages$19$valid;
    wire  [33:0] stages$19$p;
    wire  [24:0] stages$19$x;
    wire  [33:0] stages$19$d;
    wire  stages$19$neg;
    reg  stages$20$clock;
    reg  stages$20$enable;
    reg  stages$20$valid_in;
    reg  [33:0] stages$20$p_in;
    reg  [24:0] stages$20$x_in;
    reg  [33:0] stages$20$d_in;
    reg  stages$20$neg_in;
    wire  stages$20$valid;
    wire  [33:0] stages$20$p;
    wire  [24:0] stages$20$x;
    wire  [33:0] stages$20$d;
    wire  stages$20$neg;
    reg  stages$21$clock;
    reg  stages$21$enable;
    reg  stages$21$valid_in;
    reg  [33:0] stages$21$p_in;
    reg  [24:0] stages$21$x_in;
    reg  [33:0] stages$21$d_in;
    reg  stages$21$neg_in;
    wire  stages$21$valid;
    wire  [33:0] stages$21$p;
    wire  [24:0] stages$21$x;
    wire  [33:0] stages$21$d;
    wire  stages$21$neg;
    reg  stages$22$clock;
    reg  stages$22$enable;
    reg  stages$22$valid_in;
    reg  [33:0] stages$22$p_in;
    reg  [24:0] stages$22$x_in;
    reg  [33:0] stages$22$d_in;
    reg  stages$22$neg_in;
    wire  stages$22$valid;
    wire  [33:0] stages$22$p;
    wire  [24:0] stages$22$x;
    wire  [33:0] stages$22$d;
    wire  stages$22$neg;
    reg  stages$23$clock;
    reg  stages$23$enable;
    reg  stages$23$valid_in;
    reg  [33:0] stages$23$p_in;
    reg  [24:0] stages$23$x_in;
    reg  [33:0] stages$23$d_in;
    reg  stages$23$neg_in;
    wire  stages$23$valid;
    wire  [33:0] stages$23$p;
    wire  [24:0] stages$23$x;
    wire  [33:0] stages$23$d;
    wire  stages$23$neg;
    reg  stages$24$clock;
    reg  stages$24$enable;
    reg  stages$24$valid_in;
    reg  [33:0] stages$24$p_in;
    reg  [24:0] stages$24$x_in;
    reg  [33:0] stages$24$d_in;
    reg  stages$24$neg_in;
    wire  stages$24$valid;
    wire  [33:0] stages$24$p;
    wire  [24:0] stages$24$x;
    wire  [33:0] stages$24$d;
    wire  stages$24$neg;
    
    // Local signals
    reg  advance;
    reg  [57:0] m;
    reg  [24:0] last_x;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$0 stages$0(
        .clock(stages$0$clock),
        .enable(stages$0$enable),
        .valid_in(stages$0$valid_in),
        .p_in(stages$0$p_in),
        .x_in(stages$0$x_in),
        .d_in(stages$0$d_in),
        .neg_in(stages$0$neg_in),
        .valid(stages$0$valid),
        .p(stages$0$p),
        .x(stages$0$x),
        .d(stages$0$d),
        .neg(stages$0$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$1 stages$1(
        .clock(stages$1$clock),
        .enable(stages$1$enable),
        .valid_in(stages$1$valid_in),
        .p_in(stages$1$p_in),
        .x_in(stages$1$x_in),
        .d_in(stages$1$d_in),
        .neg_in(stages$1$neg_in),
        .valid(stages$1$valid),
        .p(stages$1$p),
        .x(stages$1$x),
        .d(stages$1$d),
        .neg(stages$1$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$2 stages$2(
        .clock(stages$2$clock),
        .enable(stages$2$enable),
        .valid_in(stages$2$valid_in),
        .p_in(stages$2$p_in),
        .x_in(stages$2$x_in),
        .d_in(stages$2$d_in),
        .neg_in(stages$2$neg_in),
        .valid(stages$2$valid),
        .p(stages$2$p),
        .x(stages$2$x),
        .d(stages$2$d),
        .neg(stages$2$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$3 stages$3(
        .clock(stages$3$clock),
        .enable(stages$3$enable),
        .valid_in(stages$3$valid_in),
        .p_in(stages$3$p_in),
        .x_in(stages$3$x_in),
        .d_in(stages$3$d_in),
        .neg_in(stages$3$neg_in),
        .valid(stages$3$valid),
        .p(stages$3$p),
        .x(stages$3$x),
        .d(stages$3$d),
        .neg(stages$3$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$4 stages$4(
        .clock(stages$4$clock),
        .enable(stages$4$enable),
        .valid_in(stages$4$valid_in),
        .p_in(stages$4$p_in),
        .x_in(stages$4$x_in),
        .d_in(stages$4$d_in),
        .neg_in(stages$4$neg_in),
        .valid(stages$4$valid),
        .p(stages$4$p),
        .x(stages$4$x),
        .d(stages$4$d),
        .neg(stages$4$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$5 stages$5(
        .clock(stages$5$clock),
        .enable(stages$5$enable),
        .valid_in(stages$5$valid_in),
        .p_in(stages$5$p_in),
        .x_in(stages$5$x_in),
        .d_in(stages$5$d_in),
        .neg_in(stages$5$neg_in),
        .valid(stages$5$valid),
        .p(stages$5$p),
        .x(stages$5$x),
        .d(stages$5$d),
        .neg(stages$5$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$6 stages$6(
        .clock(stages$6$clock),
        .enable(stages$6$enable),
        .valid_in(stages$6$valid_in),
        .p_in(stages$6$p_in),
        .x_in(stages$6$x_in),
        .d_in(stages$6$d_in),
        .neg_in(stages$6$neg_in),
        .valid(stages$6$valid),
        .p(stages$6$p),
        .x(stages$6$x),
        .d(stages$6$d),
        .neg(stages$6$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$7 stages$7(
        .clock(stages$7$clock),
        .enable(stages$7$enable),
        .valid_in(stages$7$valid_in),
        .p_in(stages$7$p_in),
        .x_in(stages$7$x_in),
        .d_in(stages$7$d_in),
        .neg_in(stages$7$neg_in),
        .valid(stages$7$valid),
        .p(stages$7$p),
        .x(stages$7$x),
        .d(stages$7$d),
        .neg(stages$7$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$8 stages$8(
        .clock(stages$8$clock),
        .enable(stages$8$enable),
        .valid_in(stages$8$valid_in),
        .p_in(stages$8$p_in),
        .x_in(stages$8$x_in),
        .d_in(stages$8$d_in),
        .neg_in(stages$8$neg_in),
        .valid(stages$8$valid),
        .p(stages$8$p),
        .x(stages$8$x),
        .d(stages$8$d),
        .neg(stages$8$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$9 stages$9(
        .clock(stages$9$clock),
        .enable(stages$9$enable),
        .valid_in(stages$9$valid_in),
        .p_in(stages$9$p_in),
        .x_in(stages$9$x_in),
        .d_in(stages$9$d_in),
        .neg_in(stages$9$neg_in),
        .valid(stages$9$valid),
        .p(stages$9$p),
        .x(stages$9$x),
        .d(stages$9$d),
        .neg(stages$9$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$10 stages$10(
        .clock(stages$10$clock),
        .enable(stages$10$enable),
        .valid_in(stages$10$valid_in),
        .p_in(stages$10$p_in),
        .x_in(stages$10$x_in),
        .d_in(stages$10$d_in),
        .neg_in(stages$10$neg_in),
        .valid(stages$10$valid),
        .p(stages$10$p),
        .x(stages$10$x),
        .d(stages$10$d),
        .neg(stages$10$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$11 stages$11(
        .clock(stages$11$clock),
        .enable(stages$11$enable),
        .valid_in(stages$11$valid_in),
        .p_in(stages$11$p_in),
        .x_in(stages$11$x_in),
        .d_in(stages$11$d_in),
        .neg_in(stages$11$neg_in),
        .valid(stages$11$valid),
        .p(stages$11$p),
        .x(stages$11$x),
        .d(stages$11$d),
        .neg(stages$11$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$12 stages$12(
        .clock(stages$12$clock),
        .enable(stages$12$enable),
        .valid_in(stages$12$valid_in),
        .p_in(stages$12$p_in),
        .x_in(stages$12$x_in),
        .d_in(stages$12$d_in),
        .neg_in(stages$12$neg_in),
        .valid(stages$12$valid),
        .p(stages$12$p),
        .x(stages$12$x),
        .d(stages$12$d),
        .neg(stages$12$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$13 stages$13(
        .clock(stages$13$clock),
        .enable(stages$13$enable),
        .valid_in(stages$13$valid_in),
        .p_in(stages$13$p_in),
        .x_in(stages$13$x_in),
        .d_in(stages$13$d_in),
        .neg_in(stages$13$neg_in),
        .valid(stages$13$valid),
        .p(stages$13$p),
        .x(stages$13$x),
        .d(stages$13$d),
        .neg(stages$13$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$14 stages$14(
        .clock(stages$14$clock),
        .enable(stages$14$enable),
        .valid_in(stages$14$valid_in),
        .p_in(stages$14$p_in),
        .x_in(stages$14$x_in),
        .d_in(stages$14$d_in),
        .neg_in(stages$14$neg_in),
        .valid(stages$14$valid),
        .p(stages$14$p),
        .x(stages$14$x),
        .d(stages$14$d),
        .neg(stages$14$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$15 stages$15(
        .clock(stages$15$clock),
        .enable(stages$15$enable),
        .valid_in(stages$15$valid_in),
        .p_in(stages$15$p_in),
        .x_in(stages$15$x_in),
        .d_in(stages$15$d_in),
        .neg_in(stages$15$neg_in),
        .valid(stages$15$valid),
        .p(stages$15$p),
        .x(stages$15$x),
        .d(stages$15$d),
        .neg(stages$15$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$16 stages$16(
        .clock(stages$16$clock),
        .enable(stages$16$enable),
        .valid_in(stages$16$valid_in),
        .p_in(stages$16$p_in),
        .x_in(stages$16$x_in),
        .d_in(stages$16$d_in),
        .neg_in(stages$16$neg_in),
        .valid(stages$16$valid),
        .p(stages$16$p),
        .x(stages$16$x),
        .d(stages$16$d),
        .neg(stages$16$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$17 stages$17(
        .clock(stages$17$clock),
        .enable(stages$17$enable),
        .valid_in(stages$17$valid_in),
        .p_in(stages$17$p_in),
        .x_in(stages$17$x_in),
        .d_in(stages$17$d_in),
        .neg_in(stages$17$neg_in),
        .valid(stages$17$valid),
        .p(stages$17$p),
        .x(stages$17$x),
        .d(stages$17$d),
        .neg(stages$17$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$18 stages$18(
        .clock(stages$18$clock),
        .enable(stages$18$enable),
        .valid_in(stages$18$valid_in),
        .p_in(stages$18$p_in),
        .x_in(stages$18$x_in),
        .d_in(stages$18$d_in),
        .neg_in(stages$18$neg_in),
        .valid(stages$18$valid),
        .p(stages$18$p),
        .x(stages$18$x),
        .d(stages$18$d),
        .neg(stages$18$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$19 stages$19(
        .clock(stages$19$clock),
        .enable(stages$19$enable),
        .valid_in(stages$19$valid_in),
        .p_in(stages$19$p_in),
        .x_in(stages$19$x_in),
        .d_in(stages$19$d_in),
        .neg_in(stages$19$neg_in),
        .valid(stages$19$valid),
        .p(stages$19$p),
        .x(stages$19$x),
        .d(stages$19$d),
        .neg(stages$19$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$20 stages$20(
        .clock(stages$20$clock),
        .enable(stages$20$enable),
        .valid_in(stages$20$valid_in),
        .p_in(stages$20$p_in),
        .x_in(stages$20$x_in),
        .d_in(stages$20$d_in),
        .neg_in(stages$20$neg_in),
        .valid(stages$20$valid),
        .p(stages$20$p),
        .x(stages$20$x),
        .d(stages$20$d),
        .neg(stages$20$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$21 stages$21(
        .clock(stages$21$clock),
        .enable(stages$21$enable),
        .valid_in(stages$21$valid_in),
        .p_in(stages$21$p_in),
        .x_in(stages$21$x_in),
        .d_in(stages$21$d_in),
        .neg_in(stages$21$neg_in),
        .valid(stages$21$valid),
        .p(stages$21$p),
        .x(stages$21$x),
        .d(stages$21$d),
        .neg(stages$21$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$22 stages$22(
        .clock(stages$22$clock),
        .enable(stages$22$enable),
        .valid_in(stages$22$valid_in),
        .p_in(stages$22$p_in),
        .x_in(stages$22$x_in),
        .d_in(stages$22$d_in),
        .neg_in(stages$22$neg_in),
        .valid(stages$22$valid),
        .p(stages$22$p),
        .x(stages$22$x),
        .d(stages$22$d),
        .neg(stages$22$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$23 stages$23(
        .clock(stages$23$clock),
        .enable(stages$23$enable),
        .valid_in(stages$23$valid_in),
        .p_in(stages$23$p_in),
        .x_in(stages$23$x_in),
        .d_in(stages$23$d_in),
        .neg_in(stages$23$neg_in),
        .valid(stages$23$valid),
        .p(stages$23$p),
        .x(stages$23$x),
        .d(stages$23$d),
        .neg(stages$23$neg)
    );
    raster_top$fragments$core$triangle_setup$div$stages$24 stages$24(
        .clock(stages$24$clock),
        .enable(stages$24$enable),
        .valid_in(stages$24$valid_in),
        .p_in(stages$24$p_in),
        .x_in(stages$24$x_in),
        .d_in(stages$24$d_in),
        .neg_in(stages$24$neg_in),
        .valid(stages$24$valid),
        .p(stages$24$p),
        .x(stages$24$x),
        .d(stages$24$d),
        .neg(stages$24$neg)
    );
    
    // Update code
    always @(*) begin
        advance = ~hold & (~stages$24$valid | out_ready);
        out_valid = stages$24$valid;
        last_x = stages$24$x;
        out_r = stages$24$p;
        out_q = ((last_x) & 26'h3ffffff);
        if (stages$24$neg) begin
            out_q = ((last_x) & 26'h3ffffff) | q_sign;
        end
        stages$0$clock = clock;
        stages$0$enable = advance;
        stages$1$clock = clock;
        stages$1$enable = advance;
        stages$2$clock = clock;
        stages$2$enable = advance;
        stages$3$clock = clock;
        stages$3$enable = advance;
        stages$4$clock = clock;
        stages$4$enable = advance;
        stages$5$clock = clock;
        stages$5$enable = advance;
        stages$6$clock = clock;
        stages$6$enable = advance;
        stages$7$clock = clock;
        stages$7$enable = advance;
        stages$8$clock = clock;
        stages$8$enable = advance;
        stages$9$clock = clock;
        stages$9$enable = advance;
        stages$10$clock = clock;
        stages$10$enable = advance;
        stages$11$clock = clock;
        stages$11$enable = advance;
        stages$12$clock = clock;
        stages$12$enable = advance;
        stages$13$clock = clock;
        stages$13$enable = advance;
        stages$14$clock = clock;
        stages$14$enable = advance;
        stages$15$clock = clock;
        stages$15$enable = advance;
        stages$16$clock = clock;
        stages$16$enable = advance;
        stages$17$clock = clock;
        stages$17$enable = advance;
        stages$18$clock = clock;
        stages$18$enable = advance;
        stages$19$clock = clock;
        stages$19$enable = advance;
        stages$20$clock = clock;
        stages$20$enable = advance;
        stages$21$clock = clock;
        stages$21$enable = advance;
        stages$22$clock = clock;
        stages$22$enable = advance;
        stages$23$clock = clock;
        stages$23$enable = advance;
        stages$24$clock = clock;
        stages$24$enable = advance;
        inp_ready = advance;
        m = inp_n;
        if (inp_n[n_msb]) begin
            m = ~inp_n;
        end
        stages$0$valid_in = inp_valid;
        stages$0$p_in = ((m >> qm) & 34'h3ffffffff);
        stages$0$x_in = m[(32'h0)+:(25)];
        stages$0$d_in = inp_d;
        stages$0$neg_in = inp_n[n_msb];
        stages$1$valid_in = stages$0$valid;
        stages$1$p_in = stages$0$p;
        stages$1$x_in = stages$0$x;
        stages$1$d_in = stages$0$d;
        stages$1$neg_in = stages$0$neg;
        stages$2$valid_in = stages$1$valid;
        stages$2$p_in = stages$1$p;
        stages$2$x_in = stages$1$x;
        stages$2$d_in = stages$1$d;
        stages$2$neg_in = stages$1$neg;
        stages$3$valid_in = stages$2$valid;
        stages$3$p_in = stages$2$p;
        stages$3$x_in = stages$2$x;
        stages$3$d_in = stages$2$d;
        stages$3$neg_in = stages$2$neg;
        stages$4$valid_in = stages$3$valid;
        stages$4$p_in = stages$3$p;
        stages$4$x_in = stages$3$x;
        stages$4$d_in = stages$3$d;
        stages$4$neg_in = stages$3$neg;
        stages$5$valid_in = stages$4$valid;
        stages$5$p_in = stages$4$p;
        stages$5$x_in = stages$4$x;
        stages$5$d_in = stages$4$d;
        stages$5$neg_in = stages$4$neg;
        stages$6$valid_in = stages$5$valid;
        stages$6$p_in = stages$5$p;
        stages$6$x_in = stages$5$x;
        stages$6$d_in = stages$5$d;
        stages$6$neg_in = stages$5$neg;
        stages$7$valid_in = stages$6$valid;
        stages$7$p_in = stages$6$p;
        stages$7$x_in = stages$6$x;
        stages$7$d_in = stages$6$d;
        stages$7$neg_in = stages$6$neg;
        stages$8$valid_in = stages$7$valid;
        stages$8$p_in = stages$7$p;
        stages$8$x_in = stages$7$x;
        stages$8$d_in = stages$7$d;
        stages$8$neg_in = stages$7$neg;
        stages$9$valid_in = stages$8$valid;
        stages$9$p_in = stages$8$p;
        stages$9$x_in = stages$8$x;
        stages$9$d_in = stages$8$d;
        stages$9$neg_in = stages$8$neg;
        stages$10$valid_in = stages$9$valid;
        stages$10$p_in = stages$9$p;
        stages$10$x_in = stages$9$x;
        stages$10$d_in = stages$9$d;
        stages$10$neg_in = stages$9$neg;
        stages$11$valid_in = stages$10$valid;
        stages$11$p_in = stages$10$p;
        stages$11$x_in = stages$10$x;
        stages$11$d_in = stages$10$d;
        stages$11$neg_in = stages$10$neg;
        stages$12$valid_in = stages$11$valid;
        stages$12$p_in = stages$11$p;
        stages$12$x_in = stages$11$x;
        stages$12$d_in = stages$11$d;
        stages$12$neg_in = stages$11$neg;
        stages$13$valid_in = stages$12$valid;
        stages$13$p_in = stages$12$p;
        stages$13$x_in = stages$12$x;
        stages$13$d_in = stages$12$d;
        stages$13$neg_in = stages$12$neg;
        stages$14$valid_in = stages$13$valid;
        stages$14$p_in = stages$13$p;
        stages$14$x_in = stages$13$x;
        stages$14$d_in = stages$13$d;
        stages$14$neg_in = stages$13$neg;
        stages$15$valid_in = stages$14$valid;
        stages$15$p_in = stages$14$p;
        stages$15$x_in = stages$14$x;
        stages$15$d_in = stages$14$d;
        stages$15$neg_in = stages$14$neg;
        stages$16$valid_in = stages$15$valid;
        stages$16$p_in = stages$15$p;
        stages$16$x_in = stages$15$x;
        stages$16$d_in = stages$15$d;
        stages$16$neg_in = stages$15$neg;
        stages$17$valid_in = stages$16$valid;
        stages$17$p_in = stages$16$p;
        stages$17$x_in = stages$16$x;
        stages$17$d_in = stages$16$d;
        stages$17$neg_in = stages$16$neg;
        stages$18$valid_in = stages$17$valid;
        stages$18$p_in = stages$17$p;
        stages$18$x_in = stages$17$x;
        stages$18$d_in = stages$17$d;
        stages$18$neg_in = stages$17$neg;
        stages$19$valid_in = stages$18$valid;
        stages$19$p_in = stages$18$p;
        stages$19$x_in = stages$18$x;
        stages$19$d_in = stages$18$d;
        stages$19$neg_in = stages$18$neg;
        stages$20$valid_in = stages$19$valid;
        stages$20$p_in = stages$19$p;
        stages$20$x_in = stages$19$x;
        stages$20$d_in = stages$19$d;
        stages$20$neg_in = stages$19$neg;
        stages$21$valid_in = stages$20$valid;
        stages$21$p_in = stages$20$p;
        stages$21$x_in = stages$20$x;
        stages$21$d_in = stages$20$d;
        stages$21$neg_in = stages$20$neg;
        stages$22$valid_in = stages$21$valid;
        stages$22$p_in = stages$21$p;
        stages$22$x_in = stages$21$x;
        stages$22$d_in = stages$21$d;
        stages$22$neg_in = stages$21$neg;
        stages$23$valid_in = stages$22$valid;
        stages$23$p_in = stages$22$p;
        stages$23$x_in = stages$22$x;
        stages$23$d_in = stages$22$d;
        stages$23$neg_in = stages$22$neg;
        stages$24$valid_in = stages$23$valid;
        stages$24$p_in = stages$23$p;
        stages$24$x_in = stages$23$x;
        stages$24$d_in = stages$23$d;
        stages$24$neg_in = stages$23$neg;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div


module raster_top$fragments$core$triangle_setup$div$stages$0(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$0$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$0$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$0$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$0$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$0


module raster_top$fragments$core$triangle_setup$div$stages$0$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$0$d_r


module raster_top$fragments$core$triangle_setup$div$stages$0$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$0$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$0$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$0$p_r


module raster_top$fragments$core$triangle_setup$div$stages$0$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$0$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$0$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$0$x_r


module raster_top$fragments$core$triangle_setup$div$stages$1(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$1$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$1$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$1$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$1$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$1


module raster_top$fragments$core$triangle_setup$div$stages$1$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$1$d_r


module raster_top$fragments$core$triangle_setup$div$stages$1$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$1$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$1$p_r


module raster_top$fragments$core$triangle_setup$div$stages$1$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$1$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$1$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$1$x_r


module raster_top$fragments$core$triangle_setup$div$stages$10(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$10$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$10$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$10$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$10$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$10$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$10


module raster_top$fragments$core$triangle_setup$div$stages$10$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$10$d_r


module raster_top$fragments$core$triangle_setup$div$stages$10$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$10$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$10$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$10$p_r


module raster_top$fragments$core$triangle_setup$div$stages$10$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$10$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$10$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$10$x_r


module raster_top$fragments$core$triangle_setup$div$stages$11(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$11$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$11$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$11$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$11$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$11$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$11


module raster_top$fragments$core$triangle_setup$div$stages$11$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$11$d_r


module raster_top$fragments$core$triangle_setup$div$stages$11$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$11$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$11$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$11$p_r


module raster_top$fragments$core$triangle_setup$div$stages$11$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$11$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$11$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$11$x_r


module raster_top$fragments$core$triangle_setup$div$stages$12(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$12$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$12$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$12$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$12$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$12$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$12


module raster_top$fragments$core$triangle_setup$div$stages$12$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$12$d_r


module raster_top$fragments$core$triangle_setup$div$stages$12$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$12$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$12$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$12$p_r


module raster_top$fragments$core$triangle_setup$div$stages$12$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$12$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$12$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$12$x_r


module raster_top$fragments$core$triangle_setup$div$stages$13(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$13$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$13$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$13$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$13$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$13$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$13


module raster_top$fragments$core$triangle_setup$div$stages$13$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$13$d_r


module raster_top$fragments$core$triangle_setup$div$stages$13$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$13$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$13$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$13$p_r


module raster_top$fragments$core$triangle_setup$div$stages$13$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$13$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$13$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$13$x_r


module raster_top$fragments$core$triangle_setup$div$stages$14(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$14$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$14$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$14$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$14$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$14$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$14


module raster_top$fragments$core$triangle_setup$div$stages$14$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$14$d_r


module raster_top$fragments$core$triangle_setup$div$stages$14$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$14$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$14$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$14$p_r


module raster_top$fragments$core$triangle_setup$div$stages$14$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$14$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$14$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$14$x_r


module raster_top$fragments$core$triangle_setup$div$stages$15(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$15$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$15$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$15$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$15$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$15$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$15


module raster_top$fragments$core$triangle_setup$div$stages$15$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$15$d_r


module raster_top$fragments$core$triangle_setup$div$stages$15$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$15$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$15$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$15$p_r


module raster_top$fragments$core$triangle_setup$div$stages$15$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$15$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$15$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$15$x_r


module raster_top$fragments$core$triangle_setup$div$stages$16(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$16$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$16$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$16$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$16$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$16$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$16


module raster_top$fragments$core$triangle_setup$div$stages$16$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$16$d_r


module raster_top$fragments$core$triangle_setup$div$stages$16$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$16$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$16$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$16$p_r


module raster_top$fragments$core$triangle_setup$div$stages$16$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$16$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$16$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$16$x_r


module raster_top$fragments$core$triangle_setup$div$stages$17(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$17$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$17$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$17$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$17$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$17$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$17


module raster_top$fragments$core$triangle_setup$div$stages$17$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$17$d_r


module raster_top$fragments$core$triangle_setup$div$stages$17$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$17$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$17$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$17$p_r


module raster_top$fragments$core$triangle_setup$div$stages$17$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$17$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$17$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$17$x_r


module raster_top$fragments$core$triangle_setup$div$stages$18(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$18$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$18$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$18$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$18$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$18$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$18


module raster_top$fragments$core$triangle_setup$div$stages$18$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$18$d_r


module raster_top$fragments$core$triangle_setup$div$stages$18$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$18$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$18$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$18$p_r


module raster_top$fragments$core$triangle_setup$div$stages$18$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$18$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$18$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$18$x_r


module raster_top$fragments$core$triangle_setup$div$stages$19(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$19$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$19$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$19$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$19$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$19$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$19


module raster_top$fragments$core$triangle_setup$div$stages$19$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$19$d_r


module raster_top$fragments$core$triangle_setup$div$stages$19$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$19$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$19$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$19$p_r


module raster_top$fragments$core$triangle_setup$div$stages$19$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$19$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$19$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$19$x_r


module raster_top$fragments$core$triangle_setup$div$stages$2(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$2$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$2$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$2$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$2$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$2


module raster_top$fragments$core$triangle_setup$div$stages$2$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$2$d_r


module raster_top$fragments$core$triangle_setup$div$stages$2$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$2$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$2$p_r


module raster_top$fragments$core$triangle_setup$div$stages$2$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$2$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$2$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$2$x_r


module raster_top$fragments$core$triangle_setup$div$stages$20(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$20$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$20$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$20$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$20$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$20$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$20


module raster_top$fragments$core$triangle_setup$div$stages$20$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$20$d_r


module raster_top$fragments$core$triangle_setup$div$stages$20$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$20$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$20$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$20$p_r


module raster_top$fragments$core$triangle_setup$div$stages$20$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$20$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$20$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$20$x_r


module raster_top$fragments$core$triangle_setup$div$stages$21(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$21$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$21$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$21$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$21$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$21$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$21


module raster_top$fragments$core$triangle_setup$div$stages$21$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$21$d_r


module raster_top$fragments$core$triangle_setup$div$stages$21$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$21$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$21$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$21$p_r


module raster_top$fragments$core$triangle_setup$div$stages$21$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$21$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$21$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$21$x_r


module raster_top$fragments$core$triangle_setup$div$stages$22(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$22$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$22$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$22$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$22$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$22$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$22


module raster_top$fragments$core$triangle_setup$div$stages$22$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$22$d_r


module raster_top$fragments$core$triangle_setup$div$stages$22$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$22$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$22$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$22$p_r


module raster_top$fragments$core$triangle_setup$div$stages$22$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$22$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$22$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$22$x_r


module raster_top$fragments$core$triangle_setup$div$stages$23(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$23$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$23$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$23$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$23$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$23$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$23


module raster_top$fragments$core$triangle_setup$div$stages$23$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$23$d_r


module raster_top$fragments$core$triangle_setup$div$stages$23$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$23$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$23$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$23$p_r


module raster_top$fragments$core$triangle_setup$div$stages$23$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$23$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$23$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$23$x_r


module raster_top$fragments$core$triangle_setup$div$stages$24(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b1;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$24$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$24$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$24$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$24$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$24$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$24


module raster_top$fragments$core$triangle_setup$div$stages$24$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$24$d_r


module raster_top$fragments$core$triangle_setup$div$stages$24$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$24$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$24$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$24$p_r


module raster_top$fragments$core$triangle_setup$div$stages$24$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$24$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$24$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$24$x_r


module raster_top$fragments$core$triangle_setup$div$stages$3(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$3$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$3$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$3$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$3$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$3$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$3


module raster_top$fragments$core$triangle_setup$div$stages$3$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$3$d_r


module raster_top$fragments$core$triangle_setup$div$stages$3$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$3$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$3$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$3$p_r


module raster_top$fragments$core$triangle_setup$div$stages$3$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$3$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$3$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$3$x_r


module raster_top$fragments$core$triangle_setup$div$stages$4(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$4$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$4$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$4$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$4$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$4$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$4


module raster_top$fragments$core$triangle_setup$div$stages$4$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$4$d_r


module raster_top$fragments$core$triangle_setup$div$stages$4$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$4$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$4$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$4$p_r


module raster_top$fragments$core$triangle_setup$div$stages$4$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$4$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$4$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$4$x_r


module raster_top$fragments$core$triangle_setup$div$stages$5(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$5$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$5$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$5$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$5$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$5$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$5


module raster_top$fragments$core$triangle_setup$div$stages$5$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$5$d_r


module raster_top$fragments$core$triangle_setup$div$stages$5$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$5$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$5$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$5$p_r


module raster_top$fragments$core$triangle_setup$div$stages$5$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$5$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$5$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$5$x_r


module raster_top$fragments$core$triangle_setup$div$stages$6(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$6$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$6$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$6$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$6$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$6$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$6


module raster_top$fragments$core$triangle_setup$div$stages$6$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$6$d_r


module raster_top$fragments$core$triangle_setup$div$stages$6$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$6$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$6$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$6$p_r


module raster_top$fragments$core$triangle_setup$div$stages$6$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$6$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$6$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$6$x_r


module raster_top$fragments$core$triangle_setup$div$stages$7(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$7$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$7$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$7$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$7$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$7$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$7


module raster_top$fragments$core$triangle_setup$div$stages$7$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$7$d_r


module raster_top$fragments$core$triangle_setup$div$stages$7$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$7$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$7$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$7$p_r


module raster_top$fragments$core$triangle_setup$div$stages$7$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$7$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$7$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$7$x_r


module raster_top$fragments$core$triangle_setup$div$stages$8(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$8$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$8$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$8$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$8$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$8$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$8


module raster_top$fragments$core$triangle_setup$div$stages$8$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$8$d_r


module raster_top$fragments$core$triangle_setup$div$stages$8$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$8$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$8$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$8$p_r


module raster_top$fragments$core$triangle_setup$div$stages$8$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$8$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$8$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$8$x_r


module raster_top$fragments$core$triangle_setup$div$stages$9(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    localparam  fin = 1'b0;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [34:0] t$0;
    reg  [34:0] diff$0;
    reg  [34:0] d1;
    
    // Sub module instances
    raster_top$fragments$core$triangle_setup$div$stages$9$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$9$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$9$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$9$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    raster_top$fragments$core$triangle_setup$div$stages$9$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$1[(32'h0)+:(34)];
            x_r$d = tx$1;
            if (fin & neg_in) begin
                p_r$d = d_in - tp$1[(32'h0)+:(34)] - 32'h1;
                x_r$d = ~tx$1;
            end
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$div$stages$9


module raster_top$fragments$core$triangle_setup$div$stages$9$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$9$d_r


module raster_top$fragments$core$triangle_setup$div$stages$9$neg_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$9$neg_r


module raster_top$fragments$core$triangle_setup$div$stages$9$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$9$p_r


module raster_top$fragments$core$triangle_setup$div$stages$9$valid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$9$valid_r


module raster_top$fragments$core$triangle_setup$div$stages$9$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div$stages$9$x_r


module raster_top$fragments$core$triangle_setup$div_d(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div_d


module raster_top$fragments$core$triangle_setup$div_n(d,q,clock);
    
    // Module arguments
    input wire  [57:0] d;
    output reg  [57:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 58'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div_n


module raster_top$fragments$core$triangle_setup$div_v(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$div_v


module raster_top$fragments$core$triangle_setup$exp$0(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$exp$0


module raster_top$fragments$core$triangle_setup$exp$1(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$exp$1


module raster_top$fragments$core$triangle_setup$exp$2(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$exp$2


module raster_top$fragments$core$triangle_setup$exp$3(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$exp$3


module raster_top$fragments$core$triangle_setup$exp$4(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$exp$4


module raster_top$fragments$core$triangle_setup$exp$5(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$exp$5


module raster_top$fragments$core$triangle_setup$g0(word,maj_left,start_x$0,start_x$1,start_x$2,kdx$0,kdx$1,kdx$2,kdy$0,kdy$1,kdy$2,up,edx$0,edx$1,edx$2,edy$0,edy$1,edy$2,edy_d$0,edy_d$1,edy_d$2,ed16$0,ed16$1,ed16$2,cy$0,cy$1,cy$2,count$0,count$1,count$2,used$0,used$1,used$2,step$0,step$1,step$2,toff$0,toff$1,toff$2,xf$0,xf$1,xf$2,xi$0,xi$1,xi$2,off_x$0,off_x$1,off_x$2,off_y$0,off_y$1,off_y$2,dmaj$0,dmaj$1,dmaj$2,dmaj$3,dbot$0,dbot$1,dbot$2,dbot$3,attr0$0,attr0$1,attr0$2,attr0$3);
    
    // Module arguments
    input wire  [1351:0] word;
    input wire  maj_left;
    input wire  [18:0] start_x$0;
    input wire  [18:0] start_x$1;
    input wire  [18:0] start_x$2;
    output reg  [57:0] kdx$0;
    output reg  [57:0] kdx$1;
    output reg  [57:0] kdx$2;
    output reg  [56:0] kdy$0;
    output reg  [56:0] kdy$1;
    output reg  [56:0] kdy$2;
    output reg  up;
    output reg  [57:0] edx$0;
    output reg  [57:0] edx$1;
    output reg  [57:0] edx$2;
    output reg  [56:0] edy$0;
    output reg  [56:0] edy$1;
    output reg  [56:0] edy$2;
    output reg  [33:0] edy_d$0;
    output reg  [33:0] edy_d$1;
    output reg  [33:0] edy_d$2;
    output reg  [33:0] ed16$0;
    output reg  [33:0] ed16$1;
    output reg  [33:0] ed16$2;
    output reg  [18:0] cy$0;
    output reg  [18:0] cy$1;
    output reg  [18:0] cy$2;
    output reg  [12:0] count$0;
    output reg  [12:0] count$1;
    output reg  [12:0] count$2;
    output reg  used$0;
    output reg  used$1;
    output reg  used$2;
    output reg  step$0;
    output reg  step$1;
    output reg  step$2;
    output reg  [18:0] toff$0;
    output reg  [18:0] toff$1;
    output reg  [18:0] toff$2;
    output reg  [18:0] xf$0;
    output reg  [18:0] xf$1;
    output reg  [18:0] xf$2;
    output reg  [18:0] xi$0;
    output reg  [18:0] xi$1;
    output reg  [18:0] xi$2;
    output reg  [18:0] off_x$0;
    output reg  [18:0] off_x$1;
    output reg  [18:0] off_x$2;
    output reg  [18:0] off_y$0;
    output reg  [18:0] off_y$1;
    output reg  [18:0] off_y$2;
    output reg  [18:0] dmaj$0;
    output reg  [18:0] dmaj$1;
    output reg  [18:0] dmaj$2;
    output reg  [18:0] dmaj$3;
    output reg  [18:0] dbot$0;
    output reg  [18:0] dbot$1;
    output reg  [18:0] dbot$2;
    output reg  [18:0] dbot$3;
    output reg  [39:0] attr0$0;
    output reg  [39:0] attr0$1;
    output reg  [39:0] attr0$2;
    output reg  [39:0] attr0$3;
    
    // Constant declarations
    localparam  frac = 8'h4;
    localparam  half = 19'b1000;
    
    // Local signals
    reg  [18:0] xn0;
    reg  [18:0] tracked$0;
    reg  [18:0] tracked$1;
    reg  [18:0] tracked$2;
    
    // Update code
    always @(*) begin
        kdx$0 = word[(64'h0)+:(58)];
        kdx$1 = word[(64'h3a)+:(58)];
        kdx$2 = word[(64'h74)+:(58)];
        kdy$0 = word[(64'hae)+:(57)];
        kdy$1 = word[(64'he7)+:(57)];
        kdy$2 = word[(64'h120)+:(57)];
        up = word[(64'h159)+:(1)];
        edx$0 = word[(64'h15a)+:(58)];
        edx$1 = word[(64'h194)+:(58)];
        edx$2 = word[(64'h1ce)+:(58)];
        edy$0 = word[(64'h208)+:(57)];
        edy$1 = word[(64'h241)+:(57)];
        edy$2 = word[(64'h27a)+:(57)];
        cy$0 = word[(64'h2b3)+:(19)];
        cy$1 = word[(64'h2c6)+:(19)];
        cy$2 = word[(64'h2d9)+:(19)];
        count$0 = word[(64'h2ec)+:(13)];
        count$1 = word[(64'h2f9)+:(13)];
        count$2 = word[(64'h306)+:(13)];
        used$0 = word[(64'h313)+:(1)];
        used$1 = word[(64'h314)+:(1)];
        used$2 = word[(64'h315)+:(1)];
        step$0 = word[(64'h316)+:(1)];
        step$1 = word[(64'h317)+:(1)];
        step$2 = word[(64'h318)+:(1)];
        toff$0 = word[(64'h319)+:(19)];
        toff$1 = word[(64'h32c)+:(19)];
        toff$2 = word[(64'h33f)+:(19)];
        xf$0 = word[(64'h352)+:(19)];
        xf$1 = word[(64'h365)+:(19)];
        xf$2 = word[(64'h378)+:(19)];
        xi$0 = word[(64'h38b)+:(19)];
        xi$1 = word[(64'h39e)+:(19)];
        xi$2 = word[(64'h3b1)+:(19)];
        off_y$0 = word[(64'h3c4)+:(19)];
        off_y$1 = word[(64'h3d7)+:(19)];
        off_y$2 = word[(64'h3ea)+:(19)];
        dmaj$0 = word[(64'h3fd)+:(19)];
        dmaj$1 = word[(64'h410)+:(19)];
        dmaj$2 = word[(64'h423)+:(19)];
        dmaj$3 = word[(64'h436)+:(19)];
        dbot$0 = word[(64'h449)+:(19)];
        dbot$1 = word[(64'h45c)+:(19)];
        dbot$2 = word[(64'h46f)+:(19)];
        dbot$3 = word[(64'h482)+:(19)];
        attr0$0 = word[(64'h495)+:(40)];
        attr0$1 = word[(64'h4bd)+:(40)];
        attr0$2 = word[(64'h4e5)+:(40)];
        attr0$3 = word[(64'h50d)+:(40)];
        xn0 = word[(64'h535)+:(19)];
        edy_d$0 = ((edy$0) & 34'h3ffffffff);
        edy_d$1 = ((edy$1) & 34'h3ffffffff);
        edy_d$2 = ((edy$2) & 34'h3ffffffff);
        tracked$0 = start_x$0 - 32'h1;
        if (maj_left) begin
            tracked$0 = start_x$0;
        end
        tracked$1 = start_x$1;
        if (maj_left) begin
            tracked$1 = start_x$1 - 32'h1;
        end
        tracked$2 = start_x$2;
        if (maj_left) begin
            tracked$2 = start_x$2 - 32'h1;
        end
        ed16$0 = edy_d$0 << frac;
        off_x$0 = (tracked$0 << frac) + half - xn0;
        ed16$1 = edy_d$1 << frac;
        off_x$1 = (tracked$1 << frac) + half - xn0;
        ed16$2 = edy_d$2 << frac;
        off_x$2 = (tracked$2 << frac) + half - xn0;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$g0


module raster_top$fragments$core$triangle_setup$g1(word,maj_left,start_x$0,start_x$1,start_x$2,kdx$0,kdx$1,kdx$2,kdy$0,kdy$1,kdy$2,up,edx$0,edx$1,edx$2,edy$0,edy$1,edy$2,edy_d$0,edy_d$1,edy_d$2,ed16$0,ed16$1,ed16$2,cy$0,cy$1,cy$2,count$0,count$1,count$2,used$0,used$1,used$2,step$0,step$1,step$2,toff$0,toff$1,toff$2,xf$0,xf$1,xf$2,xi$0,xi$1,xi$2,off_x$0,off_x$1,off_x$2,off_y$0,off_y$1,off_y$2,dmaj$0,dmaj$1,dmaj$2,dmaj$3,dbot$0,dbot$1,dbot$2,dbot$3,attr0$0,attr0$1,attr0$2,attr0$3);
    
    // Module arguments
    input wire  [1351:0] word;
    input wire  maj_left;
    input wire  [18:0] start_x$0;
    input wire  [18:0] start_x$1;
    input wire  [18:0] start_x$2;
    output reg  [57:0] kdx$0;
    output reg  [57:0] kdx$1;
    output reg  [57:0] kdx$2;
    output reg  [56:0] kdy$0;
    output reg  [56:0] kdy$1;
    output reg  [56:0] kdy$2;
    output reg  up;
    output reg  [57:0] edx$0;
    output reg  [57:0] edx$1;
    output reg  [57:0] edx$2;
    output reg  [56:0] edy$0;
    output reg  [56:0] edy$1;
    output reg  [56:0] edy$2;
    output reg  [33:0] edy_d$0;
    output reg  [33:0] edy_d$1;
    output reg  [33:0] edy_d$2;
    output reg  [33:0] ed16$0;
    output reg  [33:0] ed16$1;
    output reg  [33:0] ed16$2;
    output reg  [18:0] cy$0;
    output reg  [18:0] cy$1;
    output reg  [18:0] cy$2;
    output reg  [12:0] count$0;
    output reg  [12:0] count$1;
    output reg  [12:0] count$2;
    output reg  used$0;
    output reg  used$1;
    output reg  used$2;
    output reg  step$0;
    output reg  step$1;
    output reg  step$2;
    output reg  [18:0] toff$0;
    output reg  [18:0] toff$1;
    output reg  [18:0] toff$2;
    output reg  [18:0] xf$0;
    output reg  [18:0] xf$1;
    output reg  [18:0] xf$2;
    output reg  [18:0] xi$0;
    output reg  [18:0] xi$1;
    output reg  [18:0] xi$2;
    output reg  [18:0] off_x$0;
    output reg  [18:0] off_x$1;
    output reg  [18:0] off_x$2;
    output reg  [18:0] off_y$0;
    output reg  [18:0] off_y$1;
    output reg  [18:0] off_y$2;
    output reg  [18:0] dmaj$0;
    output reg  [18:0] dmaj$1;
    output reg  [18:0] dmaj$2;
    output reg  [18:0] dmaj$3;
    output reg  [18:0] dbot$0;
    output reg  [18:0] dbot$1;
    output reg  [18:0] dbot$2;
    output reg  [18:0] dbot$3;
    output reg  [39:0] attr0$0;
    output reg  [39:0] attr0$1;
    output reg  [39:0] attr0$2;
    output reg  [39:0] attr0$3;
    
    // Constant declarations
    localparam  frac = 8'h4;
    localparam  half = 19'b1000;
    
    // Local signals
    reg  [18:0] xn0;
    reg  [18:0] tracked$0;
    reg  [18:0] tracked$1;
    reg  [18:0] tracked$2;
    
    // Update code
    always @(*) begin
        kdx$0 = word[(64'h0)+:(58)];
        kdx$1 = word[(64'h3a)+:(58)];
        kdx$2 = word[(64'h74)+:(58)];
        kdy$0 = word[(64'hae)+:(57)];
        kdy$1 = word[(64'he7)+:(57)];
        kdy$2 = word[(64'h120)+:(57)];
        up = word[(64'h159)+:(1)];
        edx$0 = word[(64'h15a)+:(58)];
        edx$1 = word[(64'h194)+:(58)];
        edx$2 = word[(64'h1ce)+:(58)];
        edy$0 = word[(64'h208)+:(57)];
        edy$1 = word[(64'h241)+:(57)];
        edy$2 = word[(64'h27a)+:(57)];
        cy$0 = word[(64'h2b3)+:(19)];
        cy$1 = word[(64'h2c6)+:(19)];
        cy$2 = word[(64'h2d9)+:(19)];
        count$0 = word[(64'h2ec)+:(13)];
        count$1 = word[(64'h2f9)+:(13)];
        count$2 = word[(64'h306)+:(13)];
        used$0 = word[(64'h313)+:(1)];
        used$1 = word[(64'h314)+:(1)];
        used$2 = word[(64'h315)+:(1)];
        step$0 = word[(64'h316)+:(1)];
        step$1 = word[(64'h317)+:(1)];
        step$2 = word[(64'h318)+:(1)];
        toff$0 = word[(64'h319)+:(19)];
        toff$1 = word[(64'h32c)+:(19)];
        toff$2 = word[(64'h33f)+:(19)];
        xf$0 = word[(64'h352)+:(19)];
        xf$1 = word[(64'h365)+:(19)];
        xf$2 = word[(64'h378)+:(19)];
        xi$0 = word[(64'h38b)+:(19)];
        xi$1 = word[(64'h39e)+:(19)];
        xi$2 = word[(64'h3b1)+:(19)];
        off_y$0 = word[(64'h3c4)+:(19)];
        off_y$1 = word[(64'h3d7)+:(19)];
        off_y$2 = word[(64'h3ea)+:(19)];
        dmaj$0 = word[(64'h3fd)+:(19)];
        dmaj$1 = word[(64'h410)+:(19)];
        dmaj$2 = word[(64'h423)+:(19)];
        dmaj$3 = word[(64'h436)+:(19)];
        dbot$0 = word[(64'h449)+:(19)];
        dbot$1 = word[(64'h45c)+:(19)];
        dbot$2 = word[(64'h46f)+:(19)];
        dbot$3 = word[(64'h482)+:(19)];
        attr0$0 = word[(64'h495)+:(40)];
        attr0$1 = word[(64'h4bd)+:(40)];
        attr0$2 = word[(64'h4e5)+:(40)];
        attr0$3 = word[(64'h50d)+:(40)];
        xn0 = word[(64'h535)+:(19)];
        edy_d$0 = ((edy$0) & 34'h3ffffffff);
        edy_d$1 = ((edy$1) & 34'h3ffffffff);
        edy_d$2 = ((edy$2) & 34'h3ffffffff);
        tracked$0 = start_x$0 - 32'h1;
        if (maj_left) begin
            tracked$0 = start_x$0;
        end
        tracked$1 = start_x$1;
        if (maj_left) begin
            tracked$1 = start_x$1 - 32'h1;
        end
        tracked$2 = start_x$2;
        if (maj_left) begin
            tracked$2 = start_x$2 - 32'h1;
        end
        ed16$0 = edy_d$0 << frac;
        off_x$0 = (tracked$0 << frac) + half - xn0;
        ed16$1 = edy_d$1 << frac;
        off_x$1 = (tracked$1 << frac) + half - xn0;
        ed16$2 = edy_d$2 << frac;
        off_x$2 = (tracked$2 << frac) + half - xn0;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$g1


module raster_top$fragments$core$triangle_setup$g2(word,maj_left,start_x$0,start_x$1,start_x$2,kdx$0,kdx$1,kdx$2,kdy$0,kdy$1,kdy$2,up,edx$0,edx$1,edx$2,edy$0,edy$1,edy$2,edy_d$0,edy_d$1,edy_d$2,ed16$0,ed16$1,ed16$2,cy$0,cy$1,cy$2,count$0,count$1,count$2,used$0,used$1,used$2,step$0,step$1,step$2,toff$0,toff$1,toff$2,xf$0,xf$1,xf$2,xi$0,xi$1,xi$2,off_x$0,off_x$1,off_x$2,off_y$0,off_y$1,off_y$2,dmaj$0,dmaj$1,dmaj$2,dmaj$3,dbot$0,dbot$1,dbot$2,dbot$3,attr0$0,attr0$1,attr0$2,attr0$3);
    
    // Module arguments
    input wire  [1351:0] word;
    input wire  maj_left;
    input wire  [18:0] start_x$0;
    input wire  [18:0] start_x$1;
    input wire  [18:0] start_x$2;
    output reg  [57:0] kdx$0;
    output reg  [57:0] kdx$1;
    output reg  [57:0] kdx$2;
    output reg  [56:0] kdy$0;
    output reg  [56:0] kdy$1;
    output reg  [56:0] kdy$2;
    output reg  up;
    output reg  [57:0] edx$0;
    output reg  [57:0] edx$1;
    output reg  [57:0] edx$2;
    output reg  [56:0] edy$0;
    output reg  [56:0] edy$1;
    output reg  [56:0] edy$2;
    output reg  [33:0] edy_d$0;
    output reg  [33:0] edy_d$1;
    output reg  [33:0] edy_d$2;
    output reg  [33:0] ed16$0;
    output reg  [33:0] ed16$1;
    output reg  [33:0] ed16$2;
    output reg  [18:0] cy$0;
    output reg  [18:0] cy$1;
    output reg  [18:0] cy$2;
    output reg  [12:0] count$0;
    output reg  [12:0] count$1;
    output reg  [12:0] count$2;
    output reg  used$0;
    output reg  used$1;
    output reg  used$2;
    output reg  step$0;
    output reg  step$1;
    output reg  step$2;
    output reg  [18:0] toff$0;
    output reg  [18:0] toff$1;
    output reg  [18:0] toff$2;
    output reg  [18:0] xf$0;
    output reg  [18:0] xf$1;
    output reg  [18:0] xf$2;
    output reg  [18:0] xi$0;
    output reg  [18:0] xi$1;
    output reg  [18:0] xi$2;
    output reg  [18:0] off_x$0;
    output reg  [18:0] off_x$1;
    output reg  [18:0] off_x$2;
    output reg  [18:0] off_y$0;
    output reg  [18:0] off_y$1;
    output reg  [18:0] off_y$2;
    output reg  [18:0] dmaj$0;
    output reg  [18:0] dmaj$1;
    output reg  [18:0] dmaj$2;
    output reg  [18:0] dmaj$3;
    output reg  [18:0] dbot$0;
    output reg  [18:0] dbot$1;
    output reg  [18:0] dbot$2;
    output reg  [18:0] dbot$3;
    output reg  [39:0] attr0$0;
    output reg  [39:0] attr0$1;
    output reg  [39:0] attr0$2;
    output reg  [39:0] attr0$3;
    
    // Constant declarations
    localparam  frac = 8'h4;
    localparam  half = 19'b1000;
    
    // Local signals
    reg  [18:0] xn0;
    reg  [18:0] tracked$0;
    reg  [18:0] tracked$1;
    reg  [18:0] tracked$2;
    
    // Update code
    always @(*) begin
        kdx$0 = word[(64'h0)+:(58)];
        kdx$1 = word[(64'h3a)+:(58)];
        kdx$2 = word[(64'h74)+:(58)];
        kdy$0 = word[(64'hae)+:(57)];
        kdy$1 = word[(64'he7)+:(57)];
        kdy$2 = word[(64'h120)+:(57)];
        up = word[(64'h159)+:(1)];
        edx$0 = word[(64'h15a)+:(58)];
        edx$1 = word[(64'h194)+:(58)];
        edx$2 = word[(64'h1ce)+:(58)];
        edy$0 = word[(64'h208)+:(57)];
        edy$1 = word[(64'h241)+:(57)];
        edy$2 = word[(64'h27a)+:(57)];
        cy$0 = word[(64'h2b3)+:(19)];
        cy$1 = word[(64'h2c6)+:(19)];
        cy$2 = word[(64'h2d9)+:(19)];
        count$0 = word[(64'h2ec)+:(13)];
        count$1 = word[(64'h2f9)+:(13)];
        count$2 = word[(64'h306)+:(13)];
        used$0 = word[(64'h313)+:(1)];
        used$1 = word[(64'h314)+:(1)];
        used$2 = word[(64'h315)+:(1)];
        step$0 = word[(64'h316)+:(1)];
        step$1 = word[(64'h317)+:(1)];
        step$2 = word[(64'h318)+:(1)];
        toff$0 = word[(64'h319)+:(19)];
        toff$1 = word[(64'h32c)+:(19)];
        toff$2 = word[(64'h33f)+:(19)];
        xf$0 = word[(64'h352)+:(19)];
        xf$1 = word[(64'h365)+:(19)];
        xf$2 = word[(64'h378)+:(19)];
        xi$0 = word[(64'h38b)+:(19)];
        xi$1 = word[(64'h39e)+:(19)];
        xi$2 = word[(64'h3b1)+:(19)];
        off_y$0 = word[(64'h3c4)+:(19)];
        off_y$1 = word[(64'h3d7)+:(19)];
        off_y$2 = word[(64'h3ea)+:(19)];
        dmaj$0 = word[(64'h3fd)+:(19)];
        dmaj$1 = word[(64'h410)+:(19)];
        dmaj$2 = word[(64'h423)+:(19)];
        dmaj$3 = word[(64'h436)+:(19)];
        dbot$0 = word[(64'h449)+:(19)];
        dbot$1 = word[(64'h45c)+:(19)];
        dbot$2 = word[(64'h46f)+:(19)];
        dbot$3 = word[(64'h482)+:(19)];
        attr0$0 = word[(64'h495)+:(40)];
        attr0$1 = word[(64'h4bd)+:(40)];
        attr0$2 = word[(64'h4e5)+:(40)];
        attr0$3 = word[(64'h50d)+:(40)];
        xn0 = word[(64'h535)+:(19)];
        edy_d$0 = ((edy$0) & 34'h3ffffffff);
        edy_d$1 = ((edy$1) & 34'h3ffffffff);
        edy_d$2 = ((edy$2) & 34'h3ffffffff);
        tracked$0 = start_x$0 - 32'h1;
        if (maj_left) begin
            tracked$0 = start_x$0;
        end
        tracked$1 = start_x$1;
        if (maj_left) begin
            tracked$1 = start_x$1 - 32'h1;
        end
        tracked$2 = start_x$2;
        if (maj_left) begin
            tracked$2 = start_x$2 - 32'h1;
        end
        ed16$0 = edy_d$0 << frac;
        off_x$0 = (tracked$0 << frac) + half - xn0;
        ed16$1 = edy_d$1 << frac;
        off_x$1 = (tracked$1 << frac) + half - xn0;
        ed16$2 = edy_d$2 << frac;
        off_x$2 = (tracked$2 << frac) + half - xn0;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$g2


module raster_top$fragments$core$triangle_setup$g3(word,maj_left,start_x$0,start_x$1,start_x$2,kdx$0,kdx$1,kdx$2,kdy$0,kdy$1,kdy$2,up,edx$0,edx$1,edx$2,edy$0,edy$1,edy$2,edy_d$0,edy_d$1,edy_d$2,ed16$0,ed16$1,ed16$2,cy$0,cy$1,cy$2,count$0,count$1,count$2,used$0,used$1,used$2,step$0,step$1,step$2,toff$0,toff$1,toff$2,xf$0,xf$1,xf$2,xi$0,xi$1,xi$2,off_x$0,off_x$1,off_x$2,off_y$0,off_y$1,off_y$2,dmaj$0,dmaj$1,dmaj$2,dmaj$3,dbot$0,dbot$1,dbot$2,dbot$3,attr0$0,attr0$1,attr0$2,attr0$3);
    
    // Module arguments
    input wire  [1351:0] word;
    input wire  maj_left;
    input wire  [18:0] start_x$0;
    input wire  [18:0] start_x$1;
    input wire  [18:0] start_x$2;
    output reg  [57:0] kdx$0;
    output reg  [57:0] kdx$1;
    output reg  [57:0] kdx$2;
    output reg  [56:0] kdy$0;
    output reg  [56:0] kdy$1;
    output reg  [56:0] kdy$2;
    output reg  up;
    output reg  [57:0] edx$0;
    output reg  [57:0] edx$1;
    output reg  [57:0] edx$2;
    output reg  [56:0] edy$0;
    output reg  [56:0] edy$1;
    output reg  [56:0] edy$2;
    output reg  [33:0] edy_d$0;
    output reg  [33:0] edy_d$1;
    output reg  [33:0] edy_d$2;
    output reg  [33:0] ed16$0;
    output reg  [33:0] ed16$1;
    output reg  [33:0] ed16$2;
    output reg  [18:0] cy$0;
    output reg  [18:0] cy$1;
    output reg  [18:0] cy$2;
    output reg  [12:0] count$0;
    output reg  [12:0] count$1;
    output reg  [12:0] count$2;
    output reg  used$0;
    output reg  used$1;
    output reg  used$2;
    output reg  step$0;
    output reg  step$1;
    output reg  step$2;
    output reg  [18:0] toff$0;
    output reg  [18:0] toff$1;
    output reg  [18:0] toff$2;
    output reg  [18:0] xf$0;
    output reg  [18:0] xf$1;
    output reg  [18:0] xf$2;
    output reg  [18:0] xi$0;
    output reg  [18:0] xi$1;
    output reg  [18:0] xi$2;
    output reg  [18:0] off_x$0;
    output reg  [18:0] off_x$1;
    output reg  [18:0] off_x$2;
    output reg  [18:0] off_y$0;
    output reg  [18:0] off_y$1;
    output reg  [18:0] off_y$2;
    output reg  [18:0] dmaj$0;
    output reg  [18:0] dmaj$1;
    output reg  [18:0] dmaj$2;
    output reg  [18:0] dmaj$3;
    output reg  [18:0] dbot$0;
    output reg  [18:0] dbot$1;
    output reg  [18:0] dbot$2;
    output reg  [18:0] dbot$3;
    output reg  [39:0] attr0$0;
    output reg  [39:0] attr0$1;
    output reg  [39:0] attr0$2;
    output reg  [39:0] attr0$3;
    
    // Constant declarations
    localparam  frac = 8'h4;
    localparam  half = 19'b1000;
    
    // Local signals
    reg  [18:0] xn0;
    reg  [18:0] tracked$0;
    reg  [18:0] tracked$1;
    reg  [18:0] tracked$2;
    
    // Update code
    always @(*) begin
        kdx$0 = word[(64'h0)+:(58)];
        kdx$1 = word[(64'h3a)+:(58)];
        kdx$2 = word[(64'h74)+:(58)];
        kdy$0 = word[(64'hae)+:(57)];
        kdy$1 = word[(64'he7)+:(57)];
        kdy$2 = word[(64'h120)+:(57)];
        up = word[(64'h159)+:(1)];
        edx$0 = word[(64'h15a)+:(58)];
        edx$1 = word[(64'h194)+:(58)];
        edx$2 = word[(64'h1ce)+:(58)];
        edy$0 = word[(64'h208)+:(57)];
        edy$1 = word[(64'h241)+:(57)];
        edy$2 = word[(64'h27a)+:(57)];
        cy$0 = word[(64'h2b3)+:(19)];
        cy$1 = word[(64'h2c6)+:(19)];
        cy$2 = word[(64'h2d9)+:(19)];
        count$0 = word[(64'h2ec)+:(13)];
        count$1 = word[(64'h2f9)+:(13)];
        count$2 = word[(64'h306)+:(13)];
        used$0 = word[(64'h313)+:(1)];
        used$1 = word[(64'h314)+:(1)];
        used$2 = word[(64'h315)+:(1)];
        step$0 = word[(64'h316)+:(1)];
        step$1 = word[(64'h317)+:(1)];
        step$2 = word[(64'h318)+:(1)];
        toff$0 = word[(64'h319)+:(19)];
        toff$1 = word[(64'h32c)+:(19)];
        toff$2 = word[(64'h33f)+:(19)];
        xf$0 = word[(64'h352)+:(19)];
        xf$1 = word[(64'h365)+:(19)];
        xf$2 = word[(64'h378)+:(19)];
        xi$0 = word[(64'h38b)+:(19)];
        xi$1 = word[(64'h39e)+:(19)];
        xi$2 = word[(64'h3b1)+:(19)];
        off_y$0 = word[(64'h3c4)+:(19)];
        off_y$1 = word[(64'h3d7)+:(19)];
        off_y$2 = word[(64'h3ea)+:(19)];
        dmaj$0 = word[(64'h3fd)+:(19)];
        dmaj$1 = word[(64'h410)+:(19)];
        dmaj$2 = word[(64'h423)+:(19)];
        dmaj$3 = word[(64'h436)+:(19)];
        dbot$0 = word[(64'h449)+:(19)];
        dbot$1 = word[(64'h45c)+:(19)];
        dbot$2 = word[(64'h46f)+:(19)];
        dbot$3 = word[(64'h482)+:(19)];
        attr0$0 = word[(64'h495)+:(40)];
        attr0$1 = word[(64'h4bd)+:(40)];
        attr0$2 = word[(64'h4e5)+:(40)];
        attr0$3 = word[(64'h50d)+:(40)];
        xn0 = word[(64'h535)+:(19)];
        edy_d$0 = ((edy$0) & 34'h3ffffffff);
        edy_d$1 = ((edy$1) & 34'h3ffffffff);
        edy_d$2 = ((edy$2) & 34'h3ffffffff);
        tracked$0 = start_x$0 - 32'h1;
        if (maj_left) begin
            tracked$0 = start_x$0;
        end
        tracked$1 = start_x$1;
        if (maj_left) begin
            tracked$1 = start_x$1 - 32'h1;
        end
        tracked$2 = start_x$2;
        if (maj_left) begin
            tracked$2 = start_x$2 - 32'h1;
        end
        ed16$0 = edy_d$0 << frac;
        off_x$0 = (tracked$0 << frac) + half - xn0;
        ed16$1 = edy_d$1 << frac;
        off_x$1 = (tracked$1 << frac) + half - xn0;
        ed16$2 = edy_d$2 << frac;
        off_x$2 = (tracked$2 << frac) + half - xn0;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$g3


module raster_top$fragments$core$triangle_setup$g4(word,maj_left,start_x$0,start_x$1,start_x$2,kdx$0,kdx$1,kdx$2,kdy$0,kdy$1,kdy$2,up,edx$0,edx$1,edx$2,edy$0,edy$1,edy$2,edy_d$0,edy_d$1,edy_d$2,ed16$0,ed16$1,ed16$2,cy$0,cy$1,cy$2,count$0,count$1,count$2,used$0,used$1,used$2,step$0,step$1,step$2,toff$0,toff$1,toff$2,xf$0,xf$1,xf$2,xi$0,xi$1,xi$2,off_x$0,off_x$1,off_x$2,off_y$0,off_y$1,off_y$2,dmaj$0,dmaj$1,dmaj$2,dmaj$3,dbot$0,dbot$1,dbot$2,dbot$3,attr0$0,attr0$1,attr0$2,attr0$3);
    
    // Module arguments
    input wire  [1351:0] word;
    input wire  maj_left;
    input wire  [18:0] start_x$0;
    input wire  [18:0] start_x$1;
    input wire  [18:0] start_x$2;
    output reg  [57:0] kdx$0;
    output reg  [57:0] kdx$1;
    output reg  [57:0] kdx$2;
    output reg  [56:0] kdy$0;
    output reg  [56:0] kdy$1;
    output reg  [56:0] kdy$2;
    output reg  up;
    output reg  [57:0] edx$0;
    output reg  [57:0] edx$1;
    output reg  [57:0] edx$2;
    output reg  [56:0] edy$0;
    output reg  [56:0] edy$1;
    output reg  [56:0] edy$2;
    output reg  [33:0] edy_d$0;
    output reg  [33:0] edy_d$1;
    output reg  [33:0] edy_d$2;
    output reg  [33:0] ed16$0;
    output reg  [33:0] ed16$1;
    output reg  [33:0] ed16$2;
    output reg  [18:0] cy$0;
    output reg  [18:0] cy$1;
    output reg  [18:0] cy$2;
    output reg  [12:0] count$0;
    output reg  [12:0] count$1;
    output reg  [12:0] count$2;
    output reg  used$0;
    output reg  used$1;
    output reg  used$2;
    output reg  step$0;
    output reg  step$1;
    output reg  step$2;
    output reg  [18:0] toff$0;
    output reg  [18:0] toff$1;
    output reg  [18:0] toff$2;
    output reg  [18:0] xf$0;
    output reg  [18:0] xf$1;
    output reg  [18:0] xf$2;
    output reg  [18:0] xi$0;
    output reg  [18:0] xi$1;
    output reg  [18:0] xi$2;
    output reg  [18:0] off_x$0;
    output reg  [18:0] off_x$1;
    output reg  [18:0] off_x$2;
    output reg  [18:0] off_y$0;
    output reg  [18:0] off_y$1;
    output reg  [18:0] off_y$2;
    output reg  [18:0] dmaj$0;
    output reg  [18:0] dmaj$1;
    output reg  [18:0] dmaj$2;
    output reg  [18:0] dmaj$3;
    output reg  [18:0] dbot$0;
    output reg  [18:0] dbot$1;
    output reg  [18:0] dbot$2;
    output reg  [18:0] dbot$3;
    output reg  [39:0] attr0$0;
    output reg  [39:0] attr0$1;
    output reg  [39:0] attr0$2;
    output reg  [39:0] attr0$3;
    
    // Constant declarations
    localparam  frac = 8'h4;
    localparam  half = 19'b1000;
    
    // Local signals
    reg  [18:0] xn0;
    reg  [18:0] tracked$0;
    reg  [18:0] tracked$1;
    reg  [18:0] tracked$2;
    
    // Update code
    always @(*) begin
        kdx$0 = word[(64'h0)+:(58)];
        kdx$1 = word[(64'h3a)+:(58)];
        kdx$2 = word[(64'h74)+:(58)];
        kdy$0 = word[(64'hae)+:(57)];
        kdy$1 = word[(64'he7)+:(57)];
        kdy$2 = word[(64'h120)+:(57)];
        up = word[(64'h159)+:(1)];
        edx$0 = word[(64'h15a)+:(58)];
        edx$1 = word[(64'h194)+:(58)];
        edx$2 = word[(64'h1ce)+:(58)];
        edy$0 = word[(64'h208)+:(57)];
        edy$1 = word[(64'h241)+:(57)];
        edy$2 = word[(64'h27a)+:(57)];
        cy$0 = word[(64'h2b3)+:(19)];
        cy$1 = word[(64'h2c6)+:(19)];
        cy$2 = word[(64'h2d9)+:(19)];
        count$0 = word[(64'h2ec)+:(13)];
        count$1 = word[(64'h2f9)+:(13)];
        count$2 = word[(64'h306)+:(13)];
        used$0 = word[(64'h313)+:(1)];
        used$1 = word[(64'h314)+:(1)];
        used$2 = word[(64'h315)+:(1)];
        step$0 = word[(64'h316)+:(1)];
        step$1 = word[(64'h317)+:(1)];
        step$2 = word[(64'h318)+:(1)];
        toff$0 = word[(64'h319)+:(19)];
        toff$1 = word[(64'h32c)+:(19)];
        toff$2 = word[(64'h33f)+:(19)];
        xf$0 = word[(64'h352)+:(19)];
        xf$1 = word[(64'h365)+:(19)];
        xf$2 = word[(64'h378)+:(19)];
        xi$0 = word[(64'h38b)+:(19)];
        xi$1 = word[(64'h39e)+:(19)];
        xi$2 = word[(64'h3b1)+:(19)];
        off_y$0 = word[(64'h3c4)+:(19)];
        off_y$1 = word[(64'h3d7)+:(19)];
        off_y$2 = word[(64'h3ea)+:(19)];
        dmaj$0 = word[(64'h3fd)+:(19)];
        dmaj$1 = word[(64'h410)+:(19)];
        dmaj$2 = word[(64'h423)+:(19)];
        dmaj$3 = word[(64'h436)+:(19)];
        dbot$0 = word[(64'h449)+:(19)];
        dbot$1 = word[(64'h45c)+:(19)];
        dbot$2 = word[(64'h46f)+:(19)];
        dbot$3 = word[(64'h482)+:(19)];
        attr0$0 = word[(64'h495)+:(40)];
        attr0$1 = word[(64'h4bd)+:(40)];
        attr0$2 = word[(64'h4e5)+:(40)];
        attr0$3 = word[(64'h50d)+:(40)];
        xn0 = word[(64'h535)+:(19)];
        edy_d$0 = ((edy$0) & 34'h3ffffffff);
        edy_d$1 = ((edy$1) & 34'h3ffffffff);
        edy_d$2 = ((edy$2) & 34'h3ffffffff);
        tracked$0 = start_x$0 - 32'h1;
        if (maj_left) begin
            tracked$0 = start_x$0;
        end
        tracked$1 = start_x$1;
        if (maj_left) begin
            tracked$1 = start_x$1 - 32'h1;
        end
        tracked$2 = start_x$2;
        if (maj_left) begin
            tracked$2 = start_x$2 - 32'h1;
        end
        ed16$0 = edy_d$0 << frac;
        off_x$0 = (tracked$0 << frac) + half - xn0;
        ed16$1 = edy_d$1 << frac;
        off_x$1 = (tracked$1 << frac) + half - xn0;
        ed16$2 = edy_d$2 << frac;
        off_x$2 = (tracked$2 << frac) + half - xn0;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$g4


module raster_top$fragments$core$triangle_setup$g5(word,maj_left,start_x$0,start_x$1,start_x$2,kdx$0,kdx$1,kdx$2,kdy$0,kdy$1,kdy$2,up,edx$0,edx$1,edx$2,edy$0,edy$1,edy$2,edy_d$0,edy_d$1,edy_d$2,ed16$0,ed16$1,ed16$2,cy$0,cy$1,cy$2,count$0,count$1,count$2,used$0,used$1,used$2,step$0,step$1,step$2,toff$0,toff$1,toff$2,xf$0,xf$1,xf$2,xi$0,xi$1,xi$2,off_x$0,off_x$1,off_x$2,off_y$0,off_y$1,off_y$2,dmaj$0,dmaj$1,dmaj$2,dmaj$3,dbot$0,dbot$1,dbot$2,dbot$3,attr0$0,attr0$1,attr0$2,attr0$3);
    
    // Module arguments
    input wire  [1351:0] word;
    input wire  maj_left;
    input wire  [18:0] start_x$0;
    input wire  [18:0] start_x$1;
    input wire  [18:0] start_x$2;
    output reg  [57:0] kdx$0;
    output reg  [57:0] kdx$1;
    output reg  [57:0] kdx$2;
    output reg  [56:0] kdy$0;
    output reg  [56:0] kdy$1;
    output reg  [56:0] kdy$2;
    output reg  up;
    output reg  [57:0] edx$0;
    output reg  [57:0] edx$1;
    output reg  [57:0] edx$2;
    output reg  [56:0] edy$0;
    output reg  [56:0] edy$1;
    output reg  [56:0] edy$2;
    output reg  [33:0] edy_d$0;
    output reg  [33:0] edy_d$1;
    output reg  [33:0] edy_d$2;
    output reg  [33:0] ed16$0;
    output reg  [33:0] ed16$1;
    output reg  [33:0] ed16$2;
    output reg  [18:0] cy$0;
    output reg  [18:0] cy$1;
    output reg  [18:0] cy$2;
    output reg  [12:0] count$0;
    output reg  [12:0] count$1;
    output reg  [12:0] count$2;
    output reg  used$0;
    output reg  used$1;
    output reg  used$2;
    output reg  step$0;
    output reg  step$1;
    output reg  step$2;
    output reg  [18:0] toff$0;
    output reg  [18:0] toff$1;
    output reg  [18:0] toff$2;
    output reg  [18:0] xf$0;
    output reg  [18:0] xf$1;
    output reg  [18:0] xf$2;
    output reg  [18:0] xi$0;
    output reg  [18:0] xi$1;
    output reg  [18:0] xi$2;
    output reg  [18:0] off_x$0;
    output reg  [18:0] off_x$1;
    output reg  [18:0] off_x$2;
    output reg  [18:0] off_y$0;
    output reg  [18:0] off_y$1;
    output reg  [18:0] off_y$2;
    output reg  [18:0] dmaj$0;
    output reg  [18:0] dmaj$1;
    output reg  [18:0] dmaj$2;
    output reg  [18:0] dmaj$3;
    output reg  [18:0] dbot$0;
    output reg  [18:0] dbot$1;
    output reg  [18:0] dbot$2;
    output reg  [18:0] dbot$3;
    output reg  [39:0] attr0$0;
    output reg  [39:0] attr0$1;
    output reg  [39:0] attr0$2;
    output reg  [39:0] attr0$3;
    
    // Constant declarations
    localparam  frac = 8'h4;
    localparam  half = 19'b1000;
    
    // Local signals
    reg  [18:0] xn0;
    reg  [18:0] tracked$0;
    reg  [18:0] tracked$1;
    reg  [18:0] tracked$2;
    
    // Update code
    always @(*) begin
        kdx$0 = word[(64'h0)+:(58)];
        kdx$1 = word[(64'h3a)+:(58)];
        kdx$2 = word[(64'h74)+:(58)];
        kdy$0 = word[(64'hae)+:(57)];
        kdy$1 = word[(64'he7)+:(57)];
        kdy$2 = word[(64'h120)+:(57)];
        up = word[(64'h159)+:(1)];
        edx$0 = word[(64'h15a)+:(58)];
        edx$1 = word[(64'h194)+:(58)];
        edx$2 = word[(64'h1ce)+:(58)];
        edy$0 = word[(64'h208)+:(57)];
        edy$1 = word[(64'h241)+:(57)];
        edy$2 = word[(64'h27a)+:(57)];
        cy$0 = word[(64'h2b3)+:(19)];
        cy$1 = word[(64'h2c6)+:(19)];
        cy$2 = word[(64'h2d9)+:(19)];
        count$0 = word[(64'h2ec)+:(13)];
        count$1 = word[(64'h2f9)+:(13)];
        count$2 = word[(64'h306)+:(13)];
        used$0 = word[(64'h313)+:(1)];
        used$1 = word[(64'h314)+:(1)];
        used$2 = word[(64'h315)+:(1)];
        step$0 = word[(64'h316)+:(1)];
        step$1 = word[(64'h317)+:(1)];
        step$2 = word[(64'h318)+:(1)];
        toff$0 = word[(64'h319)+:(19)];
        toff$1 = word[(64'h32c)+:(19)];
        toff$2 = word[(64'h33f)+:(19)];
        xf$0 = word[(64'h352)+:(19)];
        xf$1 = word[(64'h365)+:(19)];
        xf$2 = word[(64'h378)+:(19)];
        xi$0 = word[(64'h38b)+:(19)];
        xi$1 = word[(64'h39e)+:(19)];
        xi$2 = word[(64'h3b1)+:(19)];
        off_y$0 = word[(64'h3c4)+:(19)];
        off_y$1 = word[(64'h3d7)+:(19)];
        off_y$2 = word[(64'h3ea)+:(19)];
        dmaj$0 = word[(64'h3fd)+:(19)];
        dmaj$1 = word[(64'h410)+:(19)];
        dmaj$2 = word[(64'h423)+:(19)];
        dmaj$3 = word[(64'h436)+:(19)];
        dbot$0 = word[(64'h449)+:(19)];
        dbot$1 = word[(64'h45c)+:(19)];
        dbot$2 = word[(64'h46f)+:(19)];
        dbot$3 = word[(64'h482)+:(19)];
        attr0$0 = word[(64'h495)+:(40)];
        attr0$1 = word[(64'h4bd)+:(40)];
        attr0$2 = word[(64'h4e5)+:(40)];
        attr0$3 = word[(64'h50d)+:(40)];
        xn0 = word[(64'h535)+:(19)];
        edy_d$0 = ((edy$0) & 34'h3ffffffff);
        edy_d$1 = ((edy$1) & 34'h3ffffffff);
        edy_d$2 = ((edy$2) & 34'h3ffffffff);
        tracked$0 = start_x$0 - 32'h1;
        if (maj_left) begin
            tracked$0 = start_x$0;
        end
        tracked$1 = start_x$1;
        if (maj_left) begin
            tracked$1 = start_x$1 - 32'h1;
        end
        tracked$2 = start_x$2;
        if (maj_left) begin
            tracked$2 = start_x$2 - 32'h1;
        end
        ed16$0 = edy_d$0 << frac;
        off_x$0 = (tracked$0 << frac) + half - xn0;
        ed16$1 = edy_d$1 << frac;
        off_x$1 = (tracked$1 << frac) + half - xn0;
        ed16$2 = edy_d$2 << frac;
        off_x$2 = (tracked$2 << frac) + half - xn0;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$g5


module raster_top$fragments$core$triangle_setup$gate_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gate_r


module raster_top$fragments$core$triangle_setup$geo$0(d,q,clock);
    
    // Module arguments
    input wire  [1351:0] d;
    output reg  [1351:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1352'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$geo$0


module raster_top$fragments$core$triangle_setup$geo$1(d,q,clock);
    
    // Module arguments
    input wire  [1351:0] d;
    output reg  [1351:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1352'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$geo$1


module raster_top$fragments$core$triangle_setup$geo$2(d,q,clock);
    
    // Module arguments
    input wire  [1351:0] d;
    output reg  [1351:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1352'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$geo$2


module raster_top$fragments$core$triangle_setup$geo$3(d,q,clock);
    
    // Module arguments
    input wire  [1351:0] d;
    output reg  [1351:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1352'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$geo$3


module raster_top$fragments$core$triangle_setup$geo$4(d,q,clock);
    
    // Module arguments
    input wire  [1351:0] d;
    output reg  [1351:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1352'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$geo$4


module raster_top$fragments$core$triangle_setup$geo$5(d,q,clock);
    
    // Module arguments
    input wire  [1351:0] d;
    output reg  [1351:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1352'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$geo$5


module raster_top$fragments$core$triangle_setup$geometry(vx$0,vx$1,vx$2,vy$0,vy$1,vy$2,vz$0,vz$1,vz$2,vc$0,vc$1,vc$2,vc$3,vc$4,vc$5,vc$6,vc$7,vc$8,crosses,word);
    
    // Module arguments
    input wire  [15:0] vx$0;
    input wire  [15:0] vx$1;
    input wire  [15:0] vx$2;
    input wire  [15:0] vy$0;
    input wire  [15:0] vy$1;
    input wire  [15:0] vy$2;
    input wire  [17:0] vz$0;
    input wire  [17:0] vz$1;
    input wire  [17:0] vz$2;
    input wire  [7:0] vc$0;
    input wire  [7:0] vc$1;
    input wire  [7:0] vc$2;
    input wire  [7:0] vc$3;
    input wire  [7:0] vc$4;
    input wire  [7:0] vc$5;
    input wire  [7:0] vc$6;
    input wire  [7:0] vc$7;
    input wire  [7:0] vc$8;
    input wire  [5:0] crosses;
    output reg  [1351:0] word;
    
    // Constant declarations
    localparam  frac = 8'h4;
    localparam  half_m1 = 19'b111;
    localparam  half = 19'b1000;
    localparam  int_mask = 19'b1111111111111110000;
    localparam  frac_mask = 19'b1111;
    localparam  xy_msb = 8'hf;
    localparam  z_msb = 8'h11;
    localparam  nb_msb = 8'h12;
    localparam  xy_ext = 58'h3ffffffffff0000;
    localparam  y_ext = 57'h1ffffffffff0000;
    localparam  z_ext = 19'b1000000000000000000;
    localparam  shr_ext = 19'b1111000000000000000;
    localparam  top_bit = 8'h2;
    localparam  bottom_bit = 8'h3;
    
    // Local signals
    reg  [57:0] kdx$0;
    reg  [57:0] kdx$1;
    reg  [57:0] kdx$2;
    reg  [56:0] kdy$0;
    reg  [56:0] kdy$1;
    reg  [56:0] kdy$2;
    reg  up;
    reg  [57:0] edx$0;
    reg  [57:0] edx$1;
    reg  [57:0] edx$2;
    reg  [56:0] edy$0;
    reg  [56:0] edy$1;
    reg  [56:0] edy$2;
    reg  [18:0] cy$0;
    reg  [18:0] cy$1;
    reg  [18:0] cy$2;
    reg  [12:0] count$0;
    reg  [12:0] count$1;
    reg  [12:0] count$2;
    reg  [18:0] toff$0;
    reg  [18:0] toff$1;
    reg  [18:0] toff$2;
    reg  [18:0] xf$0;
    reg  [18:0] xf$1;
    reg  [18:0] xf$2;
    reg  [18:0] xi$0;
    reg  [18:0] xi$1;
    reg  [18:0] xi$2;
    reg  [18:0] off_y$0;
    reg  [18:0] off_y$1;
    reg  [18:0] off_y$2;
    reg  [18:0] dmaj$0;
    reg  [18:0] dmaj$1;
    reg  [18:0] dmaj$2;
    reg  [18:0] dmaj$3;
    reg  [18:0] dbot$0;
    reg  [18:0] dbot$1;
    reg  [18:0] dbot$2;
    reg  [18:0] dbot$3;
    reg  [39:0] attr0$0;
    reg  [39:0] attr0$1;
    reg  [39:0] attr0$2;
    reg  [39:0] attr0$3;
    reg  [57:0] xw$0;
    reg  [57:0] xw$1;
    reg  [57:0] xw$2;
    reg  [56:0] yw$0;
    reg  [56:0] yw$1;
    reg  [56:0] yw$2;
    reg  [18:0] zn$0;
    reg  [18:0] zn$1;
    reg  [18:0] zn$2;
    reg  [18:0] cn$0;
    reg  [18:0] cn$1;
    reg  [18:0] cn$2;
    reg  [18:0] cn$3;
    reg  [18:0] cn$4;
    reg  [18:0] cn$5;
    reg  [18:0] cn$6;
    reg  [18:0] cn$7;
    reg  [18:0] cn$8;
    reg  [18:0] xn$0;
    reg  [18:0] xn$1;
    reg  [18:0] xn$2;
    reg  [18:0] yn$0;
    reg  [18:0] yn$1;
    reg  [18:0] yn$2;
    reg  [18:0] cv$0;
    reg  [18:0] cv$1;
    reg  [18:0] cv$2;
    reg  [12:0] span$0;
    reg  [12:0] span$1;
    reg  [12:0] span$2;
    reg  [18:0] diff$0;
    reg  [18:0] diff$1;
    reg  [18:0] diff$2;
    reg  [18:0] bx$0;
    reg  [18:0] bx$1;
    reg  [18:0] bx$2;
    reg  [18:0] by$0;
    reg  [18:0] by$1;
    reg  [18:0] by$2;
    reg  [18:0] xb$0;
    reg  [18:0] xb$1;
    reg  [18:0] xb$2;
    
    // Update code
    always @(*) begin
        xw$0 = ((vx$0) & 58'h3ffffffffffffff);
        if (vx$0[xy_msb]) begin
            xw$0 = ((vx$0) & 58'h3ffffffffffffff) | xy_ext;
        end
        xw$1 = ((vx$1) & 58'h3ffffffffffffff);
        if (vx$1[xy_msb]) begin
            xw$1 = ((vx$1) & 58'h3ffffffffffffff) | xy_ext;
        end
        xw$2 = ((vx$2) & 58'h3ffffffffffffff);
        if (vx$2[xy_msb]) begin
            xw$2 = ((vx$2) & 58'h3ffffffffffffff) | xy_ext;
        end
        yw$0 = ((vy$0) & 57'h1ffffffffffffff);
        if (vy$0[xy_msb]) begin
            yw$0 = ((vy$0) & 57'h1ffffffffffffff) | y_ext;
        end
        yw$1 = ((vy$1) & 57'h1ffffffffffffff);
        if (vy$1[xy_msb]) begin
            yw$1 = ((vy$1) & 57'h1ffffffffffffff) | y_ext;
        end
        yw$2 = ((vy$2) & 57'h1ffffffffffffff);
        if (vy$2[xy_msb]) begin
            yw$2 = ((vy$2) & 57'h1ffffffffffffff) | y_ext;
        end
        zn$0 = ((vz$0) & 19'h7ffff);
        if (vz$0[z_msb]) begin
            zn$0 = ((vz$0) & 19'h7ffff) | z_ext;
        end
        zn$1 = ((vz$1) & 19'h7ffff);
        if (vz$1[z_msb]) begin
            zn$1 = ((vz$1) & 19'h7ffff) | z_ext;
        end
        zn$2 = ((vz$2) & 19'h7ffff);
        if (vz$2[z_msb]) begin
            zn$2 = ((vz$2) & 19'h7ffff) | z_ext;
        end
        cn$0 = ((vc$0) & 19'h7ffff);
        cn$1 = ((vc$1) & 19'h7ffff);
        cn$2 = ((vc$2) & 19'h7ffff);
        cn$3 = ((vc$3) & 19'h7ffff);
        cn$4 = ((vc$4) & 19'h7ffff);
        cn$5 = ((vc$5) & 19'h7ffff);
        cn$6 = ((vc$6) & 19'h7ffff);
        cn$7 = ((vc$7) & 19'h7ffff);
        cn$8 = ((vc$8) & 19'h7ffff);
        xn$0 = xw$0[(32'h0)+:(19)];
        yn$0 = yw$0[(32'h0)+:(19)];
        cv$0 = ((yn$0 + half_m1) & int_mask) | half;
        xn$1 = xw$1[(32'h0)+:(19)];
        yn$1 = yw$1[(32'h0)+:(19)];
        cv$1 = ((yn$1 + half_m1) & int_mask) | half;
        xn$2 = xw$2[(32'h0)+:(19)];
        yn$2 = yw$2[(32'h0)+:(19)];
        cv$2 = ((yn$2 + half_m1) & int_mask) | half;
        kdx$0 = xw$2 - xw$0;
        kdy$0 = yw$2 - yw$0;
        diff$0 = cv$2 - cv$0;
        kdx$1 = xw$1 - xw$0;
        kdy$1 = yw$1 - yw$0;
        diff$1 = cv$1 - cv$0;
        kdx$2 = xw$2 - xw$1;
        kdy$2 = yw$2 - yw$1;
        diff$2 = cv$2 - cv$1;
        span$0 = diff$0[(frac)+:(13)];
        if (diff$0[nb_msb]) begin
            span$0 = 32'h0;
        end
        span$1 = diff$1[(frac)+:(13)];
        if (diff$1[nb_msb]) begin
            span$1 = 32'h0;
        end
        span$2 = diff$2[(frac)+:(13)];
        if (diff$2[nb_msb]) begin
            span$2 = 32'h0;
        end
        up = crosses[top_bit] & ~crosses[bottom_bit];
        edx$0 = kdx$0;
        edy$0 = kdy$0;
        count$0 = span$0;
        edx$1 = kdx$1;
        edy$1 = kdy$1;
        count$1 = span$1;
        edx$2 = kdx$2;
        edy$2 = kdy$2;
        count$2 = span$2;
        bx$0 = xn$0;
        by$0 = yn$0;
        cy$0 = cv$0;
        bx$1 = xn$0;
        by$1 = yn$0;
        cy$1 = cv$0;
        bx$2 = xn$1;
        by$2 = yn$1;
        cy$2 = cv$1;
        if (up) begin
            edx$1 = kdx$2;
            edy$1 = kdy$2;
            count$1 = span$2;
            edx$2 = kdx$1;
            edy$2 = kdy$1;
            count$2 = span$1;
            bx$0 = xn$2;
            by$0 = yn$2;
            cy$0 = cv$2 - (frac_mask + 32'h1);
            bx$1 = xn$2;
            by$1 = yn$2;
            cy$1 = cv$2 - (frac_mask + 32'h1);
            cy$2 = cv$1 - (frac_mask + 32'h1);
        end
        toff$0 = cy$0 - by$0;
        xb$0 = bx$0 - half;
        xf$0 = xb$0 & frac_mask;
        xi$0 = xb$0 >> frac;
        if (xb$0[nb_msb]) begin
            xi$0 = (xb$0 >> frac) | shr_ext;
        end
        off_y$0 = cy$0 - yn$0;
        toff$1 = cy$1 - by$1;
        xb$1 = bx$1 - half;
        xf$1 = xb$1 & frac_mask;
        xi$1 = xb$1 >> frac;
        if (xb$1[nb_msb]) begin
            xi$1 = (xb$1 >> frac) | shr_ext;
        end
        off_y$1 = cy$1 - yn$0;
        toff$2 = cy$2 - by$2;
        xb$2 = bx$2 - half;
        xf$2 = xb$2 & frac_mask;
        xi$2 = xb$2 >> frac;
        if (xb$2[nb_msb]) begin
            xi$2 = (xb$2 >> frac) | shr_ext;
        end
        off_y$2 = cy$2 - yn$0;
        dmaj$0 = zn$2 - zn$0;
        dbot$0 = zn$1 - zn$0;
        attr0$0 = ((zn$0) & 40'hffffffffff);
        attr0$1 = ((vc$0) & 40'hffffffffff);
        attr0$2 = ((vc$1) & 40'hffffffffff);
        attr0$3 = ((vc$2) & 40'hffffffffff);
        dmaj$1 = cn$6 - cn$0;
        dbot$1 = cn$3 - cn$0;
        dmaj$2 = cn$7 - cn$1;
        dbot$2 = cn$4 - cn$1;
        dmaj$3 = cn$8 - cn$2;
        dbot$3 = cn$5 - cn$2;
        word[(64'h0)+:(58)] = kdx$0;
        word[(64'h3a)+:(58)] = kdx$1;
        word[(64'h74)+:(58)] = kdx$2;
        word[(64'hae)+:(57)] = kdy$0;
        word[(64'he7)+:(57)] = kdy$1;
        word[(64'h120)+:(57)] = kdy$2;
        word[(64'h159)+:(1)] = up;
        word[(64'h15a)+:(58)] = edx$0;
        word[(64'h194)+:(58)] = edx$1;
        word[(64'h1ce)+:(58)] = edx$2;
        word[(64'h208)+:(57)] = edy$0;
        word[(64'h241)+:(57)] = edy$1;
        word[(64'h27a)+:(57)] = edy$2;
        word[(64'h2b3)+:(19)] = cy$0;
        word[(64'h2c6)+:(19)] = cy$1;
        word[(64'h2d9)+:(19)] = cy$2;
        word[(64'h2ec)+:(13)] = count$0;
        word[(64'h2f9)+:(13)] = count$1;
        word[(64'h306)+:(13)] = count$2;
        word[(64'h313)+:(1)] = count$0 != 32'h0;
        word[(64'h314)+:(1)] = count$1 != 32'h0;
        word[(64'h315)+:(1)] = count$2 != 32'h0;
        word[(64'h316)+:(1)] = count$0 > 32'h1;
        word[(64'h317)+:(1)] = count$1 > 32'h1;
        word[(64'h318)+:(1)] = count$2 > 32'h1;
        word[(64'h319)+:(19)] = toff$0;
        word[(64'h32c)+:(19)] = toff$1;
        word[(64'h33f)+:(19)] = toff$2;
        word[(64'h352)+:(19)] = xf$0;
        word[(64'h365)+:(19)] = xf$1;
        word[(64'h378)+:(19)] = xf$2;
        word[(64'h38b)+:(19)] = xi$0;
        word[(64'h39e)+:(19)] = xi$1;
        word[(64'h3b1)+:(19)] = xi$2;
        word[(64'h3c4)+:(19)] = off_y$0;
        word[(64'h3d7)+:(19)] = off_y$1;
        word[(64'h3ea)+:(19)] = off_y$2;
        word[(64'h3fd)+:(19)] = dmaj$0;
        word[(64'h410)+:(19)] = dmaj$1;
        word[(64'h423)+:(19)] = dmaj$2;
        word[(64'h436)+:(19)] = dmaj$3;
        word[(64'h449)+:(19)] = dbot$0;
        word[(64'h45c)+:(19)] = dbot$1;
        word[(64'h46f)+:(19)] = dbot$2;
        word[(64'h482)+:(19)] = dbot$3;
        word[(64'h495)+:(40)] = attr0$0;
        word[(64'h4bd)+:(40)] = attr0$1;
        word[(64'h4e5)+:(40)] = attr0$2;
        word[(64'h50d)+:(40)] = attr0$3;
        word[(64'h535)+:(19)] = xn$0;
    end
    
endmodule // raster_top$fragments$core$triangle_setup$geometry


module raster_top$fragments$core$triangle_setup$gx$0(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gx$0


module raster_top$fragments$core$triangle_setup$gx$1(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gx$1


module raster_top$fragments$core$triangle_setup$gx$2(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gx$2


module raster_top$fragments$core$triangle_setup$gx$3(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gx$3


module raster_top$fragments$core$triangle_setup$gy$0(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gy$0


module raster_top$fragments$core$triangle_setup$gy$1(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gy$1


module raster_top$fragments$core$triangle_setup$gy$2(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gy$2


module raster_top$fragments$core$triangle_setup$gy$3(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$gy$3


module raster_top$fragments$core$triangle_setup$inc0$0(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$0


module raster_top$fragments$core$triangle_setup$inc0$1(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$1


module raster_top$fragments$core$triangle_setup$inc0$10(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$10


module raster_top$fragments$core$triangle_setup$inc0$11(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$11


module raster_top$fragments$core$triangle_setup$inc0$2(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$2


module raster_top$fragments$core$triangle_setup$inc0$3(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$3


module raster_top$fragments$core$triangle_setup$inc0$4(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$4


module raster_top$fragments$core$triangle_setup$inc0$5(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$5


module raster_top$fragments$core$triangle_setup$inc0$6(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$6


module raster_top$fragments$core$triangle_setup$inc0$7(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$7


module raster_top$fragments$core$triangle_setup$inc0$8(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$8


module raster_top$fragments$core$triangle_setup$inc0$9(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc0$9


module raster_top$fragments$core$triangle_setup$inc1$0(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$0


module raster_top$fragments$core$triangle_setup$inc1$1(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$1


module raster_top$fragments$core$triangle_setup$inc1$10(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$10


module raster_top$fragments$core$triangle_setup$inc1$11(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$11


module raster_top$fragments$core$triangle_setup$inc1$2(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$2


module raster_top$fragments$core$triangle_setup$inc1$3(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$3


module raster_top$fragments$core$triangle_setup$inc1$4(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$4


module raster_top$fragments$core$triangle_setup$inc1$5(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$5


module raster_top$fragments$core$triangle_setup$inc1$6(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$6


module raster_top$fragments$core$triangle_setup$inc1$7(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$7


module raster_top$fragments$core$triangle_setup$inc1$8(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$8


module raster_top$fragments$core$triangle_setup$inc1$9(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$inc1$9


module raster_top$fragments$core$triangle_setup$left(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$left


module raster_top$fragments$core$triangle_setup$mant$0(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$mant$0


module raster_top$fragments$core$triangle_setup$mant$1(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$mant$1


module raster_top$fragments$core$triangle_setup$mant$2(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$mant$2


module raster_top$fragments$core$triangle_setup$mant$3(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$mant$3


module raster_top$fragments$core$triangle_setup$mant$4(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$mant$4


module raster_top$fragments$core$triangle_setup$mant$5(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$mant$5


module raster_top$fragments$core$triangle_setup$mant_s(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$mant_s


module raster_top$fragments$core$triangle_setup$mul$0(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [56:0] a;
    input wire  [18:0] b;
    output reg  [57:0] p;
    
    // Update code (custom)
    // p = low 58 bits of a * b, both signed, three registers deep (rtl::mul::SplitMul):
    // operands; partial products (a's 17-bit chunks times b's low 17 bits, one DSP
    // block each, and a times b's top 2 bits); their sum.
    reg [56:0] a_r;
    reg [18:0] b_r;
    initial a_r = 0;
    initial b_r = 0;
    wire [18:0] bx = b_r;
    reg [33:0] pp0;
    initial pp0 = 0;
    reg [33:0] pp1;
    initial pp1 = 0;
    reg [23:0] pp2;
    initial pp2 = 0;
    reg [6:0] pp3;
    initial pp3 = 0;
    reg [40:0] ph;
    initial ph = 0;
    wire [40:0] ax = a_r[40:0];
    always @(posedge clock) if (en) begin
        a_r <= a;
        b_r <= b;
        pp0 <= a_r[16:0] * bx[16:0];
        pp1 <= a_r[33:17] * bx[16:0];
        pp2 <= a_r[50:34] * bx[16:0];
        pp3 <= $signed(a_r[56:51]) * $signed({1'b0, bx[16:0]});
        ph <= ({41{bx[17]}} & ax) - ({41{bx[18]}} & {ax[39:0], 1'b0});
        p <= {pp2[23:0], pp0[33:0]} + {pp3[6:0], pp1[33:0], 17'd0} + {ph, 17'd0};
    end
    initial p = 0;
endmodule // raster_top$fragments$core$triangle_setup$mul$0


module raster_top$fragments$core$triangle_setup$mul$1(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [56:0] a;
    input wire  [18:0] b;
    output reg  [57:0] p;
    
    // Update code (custom)
    // p = low 58 bits of a * b, both signed, three registers deep (rtl::mul::SplitMul):
    // operands; partial products (a's 17-bit chunks times b's low 17 bits, one DSP
    // block each, and a times b's top 2 bits); their sum.
    reg [56:0] a_r;
    reg [18:0] b_r;
    initial a_r = 0;
    initial b_r = 0;
    wire [18:0] bx = b_r;
    reg [33:0] pp0;
    initial pp0 = 0;
    reg [33:0] pp1;
    initial pp1 = 0;
    reg [23:0] pp2;
    initial pp2 = 0;
    reg [6:0] pp3;
    initial pp3 = 0;
    reg [40:0] ph;
    initial ph = 0;
    wire [40:0] ax = a_r[40:0];
    always @(posedge clock) if (en) begin
        a_r <= a;
        b_r <= b;
        pp0 <= a_r[16:0] * bx[16:0];
        pp1 <= a_r[33:17] * bx[16:0];
        pp2 <= a_r[50:34] * bx[16:0];
        pp3 <= $signed(a_r[56:51]) * $signed({1'b0, bx[16:0]});
        ph <= ({41{bx[17]}} & ax) - ({41{bx[18]}} & {ax[39:0], 1'b0});
        p <= {pp2[23:0], pp0[33:0]} + {pp3[6:0], pp1[33:0], 17'd0} + {ph, 17'd0};
    end
    initial p = 0;
endmodule // raster_top$fragments$core$triangle_setup$mul$1


module raster_top$fragments$core$triangle_setup$mul$2(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [56:0] a;
    input wire  [18:0] b;
    output reg  [57:0] p;
    
    // Update code (custom)
    // p = low 58 bits of a * b, both signed, three registers deep (rtl::mul::SplitMul):
    // operands; partial products (a's 17-bit chunks times b's low 17 bits, one DSP
    // block each, and a times b's top 2 bits); their sum.
    reg [56:0] a_r;
    reg [18:0] b_r;
    initial a_r = 0;
    initial b_r = 0;
    wire [18:0] bx = b_r;
    reg [33:0] pp0;
    initial pp0 = 0;
    reg [33:0] pp1;
    initial pp1 = 0;
    reg [23:0] pp2;
    initial pp2 = 0;
    reg [6:0] pp3;
    initial pp3 = 0;
    reg [40:0] ph;
    initial ph = 0;
    wire [40:0] ax = a_r[40:0];
    always @(posedge clock) if (en) begin
        a_r <= a;
        b_r <= b;
        pp0 <= a_r[16:0] * bx[16:0];
        pp1 <= a_r[33:17] * bx[16:0];
        pp2 <= a_r[50:34] * bx[16:0];
        pp3 <= $signed(a_r[56:51]) * $signed({1'b0, bx[16:0]});
        ph <= ({41{bx[17]}} & ax) - ({41{bx[18]}} & {ax[39:0], 1'b0});
        p <= {pp2[23:0], pp0[33:0]} + {pp3[6:0], pp1[33:0], 17'd0} + {ph, 17'd0};
    end
    initial p = 0;
endmodule // raster_top$fragments$core$triangle_setup$mul$2


module raster_top$fragments$core$triangle_setup$mul$3(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [56:0] a;
    input wire  [18:0] b;
    output reg  [57:0] p;
    
    // Update code (custom)
    // p = low 58 bits of a * b, both signed, three registers deep (rtl::mul::SplitMul):
    // operands; partial products (a's 17-bit chunks times b's low 17 bits, one DSP
    // block each, and a times b's top 2 bits); their sum.
    reg [56:0] a_r;
    reg [18:0] b_r;
    initial a_r = 0;
    initial b_r = 0;
    wire [18:0] bx = b_r;
    reg [33:0] pp0;
    initial pp0 = 0;
    reg [33:0] pp1;
    initial pp1 = 0;
    reg [23:0] pp2;
    initial pp2 = 0;
    reg [6:0] pp3;
    initial pp3 = 0;
    reg [40:0] ph;
    initial ph = 0;
    wire [40:0] ax = a_r[40:0];
    always @(posedge clock) if (en) begin
        a_r <= a;
        b_r <= b;
        pp0 <= a_r[16:0] * bx[16:0];
        pp1 <= a_r[33:17] * bx[16:0];
        pp2 <= a_r[50:34] * bx[16:0];
        pp3 <= $signed(a_r[56:51]) * $signed({1'b0, bx[16:0]});
        ph <= ({41{bx[17]}} & ax) - ({41{bx[18]}} & {ax[39:0], 1'b0});
        p <= {pp2[23:0], pp0[33:0]} + {pp3[6:0], pp1[33:0], 17'd0} + {ph, 17'd0};
    end
    initial p = 0;
endmodule // raster_top$fragments$core$triangle_setup$mul$3


module raster_top$fragments$core$triangle_setup$mul$4(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [56:0] a;
    input wire  [18:0] b;
    output reg  [57:0] p;
    
    // Update code (custom)
    // p = low 58 bits of a * b, both signed, three registers deep (rtl::mul::SplitMul):
    // operands; partial products (a's 17-bit chunks times b's low 17 bits, one DSP
    // block each, and a times b's top 2 bits); their sum.
    reg [56:0] a_r;
    reg [18:0] b_r;
    initial a_r = 0;
    initial b_r = 0;
    wire [18:0] bx = b_r;
    reg [33:0] pp0;
    initial pp0 = 0;
    reg [33:0] pp1;
    initial pp1 = 0;
    reg [23:0] pp2;
    initial pp2 = 0;
    reg [6:0] pp3;
    initial pp3 = 0;
    reg [40:0] ph;
    initial ph = 0;
    wire [40:0] ax = a_r[40:0];
    always @(posedge clock) if (en) begin
        a_r <= a;
        b_r <= b;
        pp0 <= a_r[16:0] * bx[16:0];
        pp1 <= a_r[33:17] * bx[16:0];
        pp2 <= a_r[50:34] * bx[16:0];
        pp3 <= $signed(a_r[56:51]) * $signed({1'b0, bx[16:0]});
        ph <= ({41{bx[17]}} & ax) - ({41{bx[18]}} & {ax[39:0], 1'b0});
        p <= {pp2[23:0], pp0[33:0]} + {pp3[6:0], pp1[33:0], 17'd0} + {ph, 17'd0};
    end
    initial p = 0;
endmodule // raster_top$fragments$core$triangle_setup$mul$4


module raster_top$fragments$core$triangle_setup$mul$5(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [56:0] a;
    input wire  [18:0] b;
    output reg  [57:0] p;
    
    // Update code (custom)
    // p = low 58 bits of a * b, both signed, three registers deep (rtl::mul::SplitMul):
    // operands; partial products (a's 17-bit chunks times b's low 17 bits, one DSP
    // block each, and a times b's top 2 bits); their sum.
    reg [56:0] a_r;
    reg [18:0] b_r;
    initial a_r = 0;
    initial b_r = 0;
    wire [18:0] bx = b_r;
    reg [33:0] pp0;
    initial pp0 = 0;
    reg [33:0] pp1;
    initial pp1 = 0;
    reg [23:0] pp2;
    initial pp2 = 0;
    reg [6:0] pp3;
    initial pp3 = 0;
    reg [40:0] ph;
    initial ph = 0;
    wire [40:0] ax = a_r[40:0];
    always @(posedge clock) if (en) begin
        a_r <= a;
        b_r <= b;
        pp0 <= a_r[16:0] * bx[16:0];
        pp1 <= a_r[33:17] * bx[16:0];
        pp2 <= a_r[50:34] * bx[16:0];
        pp3 <= $signed(a_r[56:51]) * $signed({1'b0, bx[16:0]});
        ph <= ({41{bx[17]}} & ax) - ({41{bx[18]}} & {ax[39:0], 1'b0});
        p <= {pp2[23:0], pp0[33:0]} + {pp3[6:0], pp1[33:0], 17'd0} + {ph, 17'd0};
    end
    initial p = 0;
endmodule // raster_top$fragments$core$triangle_setup$mul$5


module raster_top$fragments$core$triangle_setup$mul$6(clock,en,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [56:0] a;
    input wire  [18:0] b;
    output reg  [57:0] p;
    
    // Update code (custom)
    // p = low 58 bits of a * b, both signed, three registers deep (rtl::mul::SplitMul):
    // operands; partial products (a's 17-bit chunks times b's low 17 bits, one DSP
    // block each, and a times b's top 2 bits); their sum.
    reg [56:0] a_r;
    reg [18:0] b_r;
    initial a_r = 0;
    initial b_r = 0;
    wire [18:0] bx = b_r;
    reg [33:0] pp0;
    initial pp0 = 0;
    reg [33:0] pp1;
    initial pp1 = 0;
    reg [23:0] pp2;
    initial pp2 = 0;
    reg [6:0] pp3;
    initial pp3 = 0;
    reg [40:0] ph;
    initial ph = 0;
    wire [40:0] ax = a_r[40:0];
    always @(posedge clock) if (en) begin
        a_r <= a;
        b_r <= b;
        pp0 <= a_r[16:0] * bx[16:0];
        pp1 <= a_r[33:17] * bx[16:0];
        pp2 <= a_r[50:34] * bx[16:0];
        pp3 <= $signed(a_r[56:51]) * $signed({1'b0, bx[16:0]});
        ph <= ({41{bx[17]}} & ax) - ({41{bx[18]}} & {ax[39:0], 1'b0});
        p <= {pp2[23:0], pp0[33:0]} + {pp3[6:0], pp1[33:0], 17'd0} + {ph, 17'd0};
    end
    initial p = 0;
endmodule // raster_top$fragments$core$triangle_setup$mul$6


module raster_top$fragments$core$triangle_setup$norm(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$norm


module raster_top$fragments$core$triangle_setup$nsh(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$nsh


module raster_top$fragments$core$triangle_setup$num$0(d,q,clock);
    
    // Module arguments
    input wire  [57:0] d;
    output reg  [57:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 58'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$num$0


module raster_top$fragments$core$triangle_setup$num$1(d,q,clock);
    
    // Module arguments
    input wire  [57:0] d;
    output reg  [57:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 58'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$num$1


module raster_top$fragments$core$triangle_setup$num$2(d,q,clock);
    
    // Module arguments
    input wire  [57:0] d;
    output reg  [57:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 58'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$num$2


module raster_top$fragments$core$triangle_setup$o_count$0(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_count$0


module raster_top$fragments$core$triangle_setup$o_count$1(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_count$1


module raster_top$fragments$core$triangle_setup$o_count$2(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_count$2


module raster_top$fragments$core$triangle_setup$o_d$0(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_d$0


module raster_top$fragments$core$triangle_setup$o_d$1(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_d$1


module raster_top$fragments$core$triangle_setup$o_d$2(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_d$2


module raster_top$fragments$core$triangle_setup$o_j$0(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_j$0


module raster_top$fragments$core$triangle_setup$o_j$1(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_j$1


module raster_top$fragments$core$triangle_setup$o_j$2(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_j$2


module raster_top$fragments$core$triangle_setup$o_maj_left(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_maj_left


module raster_top$fragments$core$triangle_setup$o_walk(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$o_walk


module raster_top$fragments$core$triangle_setup$off_grid_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$off_grid_r


module raster_top$fragments$core$triangle_setup$p$0(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$p$0


module raster_top$fragments$core$triangle_setup$p$1(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$p$1


module raster_top$fragments$core$triangle_setup$p$2(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$p$2


module raster_top$fragments$core$triangle_setup$p$3(d,q,clock);
    
    // Module arguments
    input wire  [56:0] d;
    output reg  [56:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 57'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$p$3


module raster_top$fragments$core$triangle_setup$phase(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$phase


module raster_top$fragments$core$triangle_setup$plane$0(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$0


module raster_top$fragments$core$triangle_setup$plane$1(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$1


module raster_top$fragments$core$triangle_setup$plane$10(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$10


module raster_top$fragments$core$triangle_setup$plane$11(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$11


module raster_top$fragments$core$triangle_setup$plane$2(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$2


module raster_top$fragments$core$triangle_setup$plane$3(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$3


module raster_top$fragments$core$triangle_setup$plane$4(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$4


module raster_top$fragments$core$triangle_setup$plane$5(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$5


module raster_top$fragments$core$triangle_setup$plane$6(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$6


module raster_top$fragments$core$triangle_setup$plane$7(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$7


module raster_top$fragments$core$triangle_setup$plane$8(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$8


module raster_top$fragments$core$triangle_setup$plane$9(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$plane$9


module raster_top$fragments$core$triangle_setup$q$0(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$0


module raster_top$fragments$core$triangle_setup$q$1(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$1


module raster_top$fragments$core$triangle_setup$q$10(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$10


module raster_top$fragments$core$triangle_setup$q$11(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$11


module raster_top$fragments$core$triangle_setup$q$12(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$12


module raster_top$fragments$core$triangle_setup$q$13(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$13


module raster_top$fragments$core$triangle_setup$q$14(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$14


module raster_top$fragments$core$triangle_setup$q$15(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$15


module raster_top$fragments$core$triangle_setup$q$16(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$16


module raster_top$fragments$core$triangle_setup$q$17(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$17


module raster_top$fragments$core$triangle_setup$q$2(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$2


module raster_top$fragments$core$triangle_setup$q$3(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$3


module raster_top$fragments$core$triangle_setup$q$4(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$4


module raster_top$fragments$core$triangle_setup$q$5(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$5


module raster_top$fragments$core$triangle_setup$q$6(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$6


module raster_top$fragments$core$triangle_setup$q$7(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$7


module raster_top$fragments$core$triangle_setup$q$8(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$8


module raster_top$fragments$core$triangle_setup$q$9(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$q$9


module raster_top$fragments$core$triangle_setup$r$0(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$0


module raster_top$fragments$core$triangle_setup$r$1(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$1


module raster_top$fragments$core$triangle_setup$r$10(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$10


module raster_top$fragments$core$triangle_setup$r$11(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$11


module raster_top$fragments$core$triangle_setup$r$12(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$12


module raster_top$fragments$core$triangle_setup$r$13(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$13


module raster_top$fragments$core$triangle_setup$r$14(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$14


module raster_top$fragments$core$triangle_setup$r$15(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$15


module raster_top$fragments$core$triangle_setup$r$16(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$16


module raster_top$fragments$core$triangle_setup$r$17(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$17


module raster_top$fragments$core$triangle_setup$r$2(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$2


module raster_top$fragments$core$triangle_setup$r$3(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$3


module raster_top$fragments$core$triangle_setup$r$4(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$4


module raster_top$fragments$core$triangle_setup$r$5(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$5


module raster_top$fragments$core$triangle_setup$r$6(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$6


module raster_top$fragments$core$triangle_setup$r$7(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$7


module raster_top$fragments$core$triangle_setup$r$8(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$8


module raster_top$fragments$core$triangle_setup$r$9(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$r$9


module raster_top$fragments$core$triangle_setup$rho$0(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$0


module raster_top$fragments$core$triangle_setup$rho$1(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$1


module raster_top$fragments$core$triangle_setup$rho$10(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$10


module raster_top$fragments$core$triangle_setup$rho$11(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$11


module raster_top$fragments$core$triangle_setup$rho$12(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$12


module raster_top$fragments$core$triangle_setup$rho$13(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$13


module raster_top$fragments$core$triangle_setup$rho$14(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$14


module raster_top$fragments$core$triangle_setup$rho$15(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$15


module raster_top$fragments$core$triangle_setup$rho$16(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$16


module raster_top$fragments$core$triangle_setup$rho$17(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$17


module raster_top$fragments$core$triangle_setup$rho$2(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$2


module raster_top$fragments$core$triangle_setup$rho$3(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$3


module raster_top$fragments$core$triangle_setup$rho$4(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$4


module raster_top$fragments$core$triangle_setup$rho$5(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$5


module raster_top$fragments$core$triangle_setup$rho$6(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$6


module raster_top$fragments$core$triangle_setup$rho$7(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$7


module raster_top$fragments$core$triangle_setup$rho$8(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$8


module raster_top$fragments$core$triangle_setup$rho$9(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rho$9


module raster_top$fragments$core$triangle_setup$rsh(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$rsh


module raster_top$fragments$core$triangle_setup$sign$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$sign$0


module raster_top$fragments$core$triangle_setup$sign$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$sign$1


module raster_top$fragments$core$triangle_setup$sign$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$sign$2


module raster_top$fragments$core$triangle_setup$sign$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$sign$3


module raster_top$fragments$core$triangle_setup$sign$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$sign$4


module raster_top$fragments$core$triangle_setup$sign$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$sign$5


module raster_top$fragments$core$triangle_setup$stall_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$stall_r


module raster_top$fragments$core$triangle_setup$tok$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$tok$0


module raster_top$fragments$core$triangle_setup$tok$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$tok$1


module raster_top$fragments$core$triangle_setup$tok$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$tok$2


module raster_top$fragments$core$triangle_setup$tok$3(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$tok$3


module raster_top$fragments$core$triangle_setup$tok$4(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$tok$4


module raster_top$fragments$core$triangle_setup$tok$5(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$tok$5


module raster_top$fragments$core$triangle_setup$x$0(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$0


module raster_top$fragments$core$triangle_setup$x$1(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$1


module raster_top$fragments$core$triangle_setup$x$10(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$10


module raster_top$fragments$core$triangle_setup$x$11(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$11


module raster_top$fragments$core$triangle_setup$x$12(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$12


module raster_top$fragments$core$triangle_setup$x$13(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$13


module raster_top$fragments$core$triangle_setup$x$14(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$14


module raster_top$fragments$core$triangle_setup$x$15(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$15


module raster_top$fragments$core$triangle_setup$x$16(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$16


module raster_top$fragments$core$triangle_setup$x$17(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$17


module raster_top$fragments$core$triangle_setup$x$2(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$2


module raster_top$fragments$core$triangle_setup$x$3(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$3


module raster_top$fragments$core$triangle_setup$x$4(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$4


module raster_top$fragments$core$triangle_setup$x$5(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$5


module raster_top$fragments$core$triangle_setup$x$6(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$6


module raster_top$fragments$core$triangle_setup$x$7(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$7


module raster_top$fragments$core$triangle_setup$x$8(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$8


module raster_top$fragments$core$triangle_setup$x$9(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$core$triangle_setup$x$9


module raster_top$fragments$cull_sort(clock,width,height,cull_back,inp$valid,inp$ready,inp$v0_x,inp$v0_y,inp$v0_z,inp$v0_c0,inp$v0_c1,inp$v0_c2,inp$v0_iw,inp$v1_x,inp$v1_y,inp$v1_z,inp$v1_c0,inp$v1_c1,inp$v1_c2,inp$v1_iw,inp$v2_x,inp$v2_y,inp$v2_z,inp$v2_c0,inp$v2_c1,inp$v2_c2,inp$v2_iw,out$valid,out$ready,out$v0_x,out$v0_y,out$v0_z,out$v0_c0,out$v0_c1,out$v0_c2,out$v0_iw,out$v1_x,out$v1_y,out$v1_z,out$v1_c0,out$v1_c1,out$v1_c2,out$v1_iw,out$v2_x,out$v2_y,out$v2_z,out$v2_c0,out$v2_c1,out$v2_c2,out$v2_iw,out$crosses,verdict$valid,verdict$code,verdict$outside,idle);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  [10:0] height;
    input wire  cull_back;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [15:0] inp$v0_x;
    input wire  [15:0] inp$v0_y;
    input wire  [17:0] inp$v0_z;
    input wire  [7:0] inp$v0_c0;
    input wire  [7:0] inp$v0_c1;
    input wire  [7:0] inp$v0_c2;
    input wire  [15:0] inp$v0_iw;
    input wire  [15:0] inp$v1_x;
    input wire  [15:0] inp$v1_y;
    input wire  [17:0] inp$v1_z;
    input wire  [7:0] inp$v1_c0;
    input wire  [7:0] inp$v1_c1;
    input wire  [7:0] inp$v1_c2;
    input wire  [15:0] inp$v1_iw;
    input wire  [15:0] inp$v2_x;
    input wire  [15:0] inp$v2_y;
    input wire  [17:0] inp$v2_z;
    input wire  [7:0] inp$v2_c0;
    input wire  [7:0] inp$v2_c1;
    input wire  [7:0] inp$v2_c2;
    input wire  [15:0] inp$v2_iw;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [15:0] out$v0_x;
    output reg  [15:0] out$v0_y;
    output reg  [17:0] out$v0_z;
    output reg  [7:0] out$v0_c0;
    output reg  [7:0] out$v0_c1;
    output reg  [7:0] out$v0_c2;
    output reg  [15:0] out$v0_iw;
    output reg  [15:0] out$v1_x;
    output reg  [15:0] out$v1_y;
    output reg  [17:0] out$v1_z;
    output reg  [7:0] out$v1_c0;
    output reg  [7:0] out$v1_c1;
    output reg  [7:0] out$v1_c2;
    output reg  [15:0] out$v1_iw;
    output reg  [15:0] out$v2_x;
    output reg  [15:0] out$v2_y;
    output reg  [17:0] out$v2_z;
    output reg  [7:0] out$v2_c0;
    output reg  [7:0] out$v2_c1;
    output reg  [7:0] out$v2_c2;
    output reg  [15:0] out$v2_iw;
    output reg  [5:0] out$crosses;
    output reg  verdict$valid;
    output reg  [1:0] verdict$code;
    output reg  [5:0] verdict$outside;
    output reg  idle;
    
    // Constant declarations
    localparam  z_max = 18'b1111111111111111;
    localparam  half = 16'h8000;
    localparam  xy_msb = 8'hf;
    localparam  z_msb = 8'h11;
    localparam  area_msb = 8'h21;
    localparam  frac = 8'h4;
    localparam  passed = 2'b0;
    localparam  outside = 2'b1;
    localparam  back_face = 2'b10;
    localparam  zero_area = 2'b11;
    
    // Stub signals
    reg  [15:0] wx$0$x;
    wire  [16:0] wx$0$y;
    reg  [15:0] wx$1$x;
    wire  [16:0] wx$1$y;
    reg  [15:0] wx$2$x;
    wire  [16:0] wx$2$y;
    reg  [15:0] wy$0$x;
    wire  [16:0] wy$0$y;
    reg  [15:0] wy$1$x;
    wire  [16:0] wy$1$y;
    reg  [15:0] wy$2$x;
    wire  [16:0] wy$2$y;
    reg  [15:0] s1x$0$d;
    wire  [15:0] s1x$0$q;
    reg  s1x$0$clock;
    reg  [15:0] s1x$1$d;
    wire  [15:0] s1x$1$q;
    reg  s1x$1$clock;
    reg  [15:0] s1x$2$d;
    wire  [15:0] s1x$2$q;
    reg  s1x$2$clock;
    reg  [15:0] s1y$0$d;
    wire  [15:0] s1y$0$q;
    reg  s1y$0$clock;
    reg  [15:0] s1y$1$d;
    wire  [15:0] s1y$1$q;
    reg  s1y$1$clock;
    reg  [15:0] s1y$2$d;
    wire  [15:0] s1y$2$q;
    reg  s1y$2$clock;
    reg  [17:0] s1z$0$d;
    wire  [17:0] s1z$0$q;
    reg  s1z$0$clock;
    reg  [17:0] s1z$1$d;
    wire  [17:0] s1z$1$q;
    reg  s1z$1$clock;
    reg  [17:0] s1z$2$d;
    wire  [17:0] s1z$2$q;
    reg  s1z$2$clock;
    reg  [7:0] s1c$0$d;
    wire  [7:0] s1c$0$q;
    reg  s1c$0$clock;
    reg  [7:0] s1c$1$d;
    wire  [7:0] s1c$1$q;
    reg  s1c$1$clock;
    reg  [7:0] s1c$2$d;
    wire  [7:0] s1c$2$q;
    reg  s1c$2$clock;
    reg  [7:0] s1c$3$d;
    wire  [7:0] s1c$3$q;
    reg  s1c$3$clock;
    reg  [7:0] s1c$4$d;
    wire  [7:0] s1c$4$q;
    reg  s1c$4$clock;
    reg  [7:0] s1c$5$d;
    wire  [7:0] s1c$5$q;
    reg  s1c$5$clock;
    reg  [7:0] s1c$6$d;
    wire  [7:0] s1c$6$q;
    reg  s1c$6$clock;
    reg  [7:0] s1c$7$d;
    wire  [7:0] s1c$7$q;
    reg  s1c$7$clock;
    reg  [7:0] s1c$8$d;
    wire  [7:0] s1c$8$q;
    reg  s1c$8$clock;
    reg  [15:0] s1iw$0$d;
    wire  [15:0] s1iw$0$q;
    reg  s1iw$0$clock;
    reg  [15:0] s1iw$1$d;
    wire  [15:0] s1iw$1$q;
    reg  s1iw$1$clock;
    reg  [15:0] s1iw$2$d;
    wire  [15:0] s1iw$2$q;
    reg  s1iw$2$clock;
    reg  [16:0] e1x$d;
    wire  [16:0] e1x$q;
    reg  e1x$clock;
    reg  [16:0] e2y$d;
    wire  [16:0] e2y$q;
    reg  e2y$clock;
    reg  [16:0] e2x$d;
    wire  [16:0] e2x$q;
    reg  e2x$clock;
    reg  [16:0] e1y$d;
    wire  [16:0] e1y$q;
    reg  e1y$clock;
    reg  [5:0] outside1$d;
    wire  [5:0] outside1$q;
    reg  outside1$clock;
    reg  [5:0] crosses1$d;
    wire  [5:0] crosses1$q;
    reg  crosses1$clock;
    reg  back1$d;
    wire  back1$q;
    reg  back1$clock;
    reg  full1$d;
    wire  full1$q;
    reg  full1$clock;
    reg  [15:0] s2x$0$d;
    wire  [15:0] s2x$0$q;
    reg  s2x$0$clock;
    reg  [15:0] s2x$1$d;
    wire  [15:0] s2x$1$q;
    reg  s2x$1$clock;
    reg  [15:0] s2x$2$d;
    wire  [15:0] s2x$2$q;
    reg  s2x$2$clock;
    reg  [15:0] s2y$0$d;
    wire  [15:0] s2y$0$q;
    reg  s2y$0$clock;
    reg  [15:0] s2y$1$d;
    wire  [15:0] s2y$1$q;
    reg  s2y$1$clock;
    reg  [15:0] s2y$2$d;
    wire  [15:0] s2y$2$q;
    reg  s2y$2$clock;
    reg  [17:0] s2z$0$d;
    wire  [17:0] s2z$0$q;
    reg  s2z$0$clock;
    reg  [17:0] s2z$1$d;
    wire  [17:0] s2z$1$q;
    reg  s2z$1$clock;
    reg  [17:0] s2z$2$d;
    wire  [17:0] s2z$2$q;
    reg  s2z$2$clock;
    reg  [7:0] s2c$0$d;
    wire  [7:0] s2c$0$q;
    reg  s2c$0$clock;
    reg  [7:0] s2c$1$d;
    wire  [7:0] s2c$1$q;
    reg  s2c$1$clock;
    reg  [7:0] s2c$2$d;
    wire  [7:0] s2c$2$q;
    reg  s2c$2$clock;
    reg  [7:0] s2c$3$d;
    wire  [7:0] s2c$3$q;
    reg  s2c$3$clock;
    reg  [7:0] s2c$4$d;
    wire  [7:0] s2c$4$q;
    reg  s2c$4$clock;
    reg  [7:0] s2c$5$d;
    wire  [7:0] s2c$5$q;
    reg  s2c$5$clock;
    reg  [7:0] s2c$6$d;
    wire  [7:0] s2c$6$q;
    reg  s2c$6$clock;
    reg  [7:0] s2c$7$d;
    wire  [7:0] s2c$7$q;
    reg  s2c$7$clock;
    reg  [7:0] s2c$8$d;
    wire  [7:0] s2c$8$q;
    reg  s2c$8$clock;
    reg  [15:0] s2iw$0$d;
    wire  [15:0] s2iw$0$q;
    reg  s2iw$0$clock;
    reg  [15:0] s2iw$1$d;
    wire  [15:0] s2iw$1$q;
    reg  s2iw$1$clock;
    reg  [15:0] s2iw$2$d;
    wire  [15:0] s2iw$2$q;
    reg  s2iw$2$clock;
    reg  [16:0] area_mul$0$a;
    reg  [16:0] area_mul$0$b;
    wire  [33:0] area_mul$0$p;
    reg  [16:0] area_mul$1$a;
    reg  [16:0] area_mul$1$b;
    wire  [33:0] area_mul$1$p;
    reg  [33:0] prod0$d;
    wire  [33:0] prod0$q;
    reg  prod0$clock;
    reg  [33:0] prod1$d;
    wire  [33:0] prod1$q;
    reg  prod1$clock;
    reg  [5:0] outside2$d;
    wire  [5:0] outside2$q;
    reg  outside2$clock;
    reg  [5:0] crosses2$d;
    wire  [5:0] crosses2$q;
    reg  crosses2$clock;
    reg  back2$d;
    wire  back2$q;
    reg  back2$clock;
    reg  full2$d;
    wire  full2$q;
    reg  full2$clock;
    reg  [15:0] sx$0$d;
    wire  [15:0] sx$0$q;
    reg  sx$0$clock;
    reg  [15:0] sx$1$d;
    wire  [15:0] sx$1$q;
    reg  sx$1$clock;
    reg  [15:0] sx$2$d;
    wire  [15:0] sx$2$q;
    reg  sx$2$clock;
    reg  [15:0] sy$0$d;
    wire  [15:0] sy$0$q;
    reg  sy$0$clock;
    reg  [15:0] sy$1$d;
    wire  [15:0] sy$1$q;
    reg  sy$1$clock;
    reg  [15:0] sy$2$d;
    wire  [15:0] sy$2$q;
    reg  sy$2$clock;
    reg  [17:0] sz$0$d;
    wire  [17:0] sz$0$q;
    reg  sz$0$clock;
    reg  [17:0] sz$1$d;
    wire  [17:0] sz$1$q;
    reg  sz$1$clock;
    reg  [17:0] sz$2$d;
    wire  [17:0] sz$2$q;
    reg  sz$2$clock;
    reg  [7:0] sc$0$d;
    wire  [7:0] sc$0$q;
    reg  sc$0$clock;
    reg  [7:0] sc$1$d;
    wire  [7:0] sc$1$q;
    reg  sc$1$clock;
    reg  [7:0] sc$2$d;
    wire  [7:0] sc$2$q;
    reg  sc$2$clock;
    reg  [7:0] sc$3$d;
    wire  [7:0] sc$3$q;
    reg  sc$3$clock;
    reg  [7:0] sc$4$d;
    wire  [7:0] sc$4$q;
    reg  sc$4$clock;
    reg  [7:0] sc$5$d;
    wire  [7:0] sc$5$q;
    reg  sc$5$clock;
    reg  [7:0] sc$6$d;
    wire  [7:0] sc$6$q;
    reg  sc$6$clock;
    reg  [7:0] sc$7$d;
    wire  [7:0] sc$7$q;
    reg  sc$7$clock;
    reg  [7:0] sc$8$d;
    wire  [7:0] sc$8$q;
    reg  sc$8$clock;
    reg  [15:0] siw$0$d;
    wire  [15:0] siw$0$q;
    reg  siw$0$clock;
    reg  [15:0] siw$1$d;
    wire  [15:0] siw$1$q;
    reg  siw$1$clock;
    reg  [15:0] siw$2$d;
    wire  [15:0] siw$2$q;
    reg  siw$2$clock;
    reg  [5:0] crosses$d;
    wire  [5:0] crosses$q;
    reg  crosses$clock;
    reg  [1:0] code_r$d;
    wire  [1:0] code_r$q;
    reg  code_r$clock;
    reg  [5:0] outside_r$d;
    wire  [5:0] outside_r$q;
    reg  outside_r$clock;
    reg  full$d;
    wire  full$q;
    reg  full$clock;
    wire  cull$on;
    
    // Local signals
    reg  [15:0] vx$0;
    reg  [15:0] vx$1;
    reg  [15:0] vx$2;
    reg  [15:0] vy$0;
    reg  [15:0] vy$1;
    reg  [15:0] vy$2;
    reg  [17:0] vz$0;
    reg  [17:0] vz$1;
    reg  [17:0] vz$2;
    reg  [7:0] vc$0;
    reg  [7:0] vc$1;
    reg  [7:0] vc$2;
    reg  [7:0] vc$3;
    reg  [7:0] vc$4;
    reg  [7:0] vc$5;
    reg  [7:0] vc$6;
    reg  [7:0] vc$7;
    reg  [7:0] vc$8;
    reg  [15:0] viw$0;
    reg  [15:0] viw$1;
    reg  [15:0] viw$2;
    reg  [5:0] oc$0;
    reg  [5:0] oc$1;
    reg  [5:0] oc$2;
    reg  left$0;
    reg  left$1;
    reg  left$2;
    reg  right_of$0;
    reg  right_of$1;
    reg  right_of$2;
    reg  top$0;
    reg  top$1;
    reg  top$2;
    reg  below$0;
    reg  below$1;
    reg  below$2;
    reg  near$0;
    reg  near$1;
    reg  near$2;
    reg  far$0;
    reg  far$1;
    reg  far$2;
    reg  [15:0] right;
    reg  [15:0] bottom;
    reg  [15:0] key$0;
    reg  [15:0] key$1;
    reg  [15:0] key$2;
    reg  le01;
    reg  le12;
    reg  le02;
    reg  gt01;
    reg  gt12;
    reg  gt02;
    reg  [1:0] rank$0;
    reg  [1:0] rank$1;
    reg  [1:0] rank$2;
    reg  [33:0] area;
    reg  [1:0] code;
    reg  take;
    reg  move1;
    reg  move2;
    reg  leave;
    reg  out_free;
    reg  s2_free;
    reg  s1_free;
    
    // Sub module instances
    raster_top$fragments$cull_sort$wx$0 wx$0(
        .x(wx$0$x),
        .y(wx$0$y)
    );
    raster_top$fragments$cull_sort$wx$1 wx$1(
        .x(wx$1$x),
        .y(wx$1$y)
    );
    raster_top$fragments$cull_sort$wx$2 wx$2(
        .x(wx$2$x),
        .y(wx$2$y)
    );
    raster_top$fragments$cull_sort$wy$0 wy$0(
        .x(wy$0$x),
        .y(wy$0$y)
    );
    raster_top$fragments$cull_sort$wy$1 wy$1(
        .x(wy$1$x),
        .y(wy$1$y)
    );
    raster_top$fragments$cull_sort$wy$2 wy$2(
        .x(wy$2$x),
        .y(wy$2$y)
    );
    raster_top$fragments$cull_sort$s1x$0 s1x$0(
        .d(s1x$0$d),
        .q(s1x$0$q),
        .clock(s1x$0$clock)
    );
    raster_top$fragments$cull_sort$s1x$1 s1x$1(
        .d(s1x$1$d),
        .q(s1x$1$q),
        .clock(s1x$1$clock)
    );
    raster_top$fragments$cull_sort$s1x$2 s1x$2(
        .d(s1x$2$d),
        .q(s1x$2$q),
        .clock(s1x$2$clock)
    );
    raster_top$fragments$cull_sort$s1y$0 s1y$0(
        .d(s1y$0$d),
        .q(s1y$0$q),
        .clock(s1y$0$clock)
    );
    raster_top$fragments$cull_sort$s1y$1 s1y$1(
        .d(s1y$1$d),
        .q(s1y$1$q),
        .clock(s1y$1$clock)
    );
    raster_top$fragments$cull_sort$s1y$2 s1y$2(
        .d(s1y$2$d),
        .q(s1y$2$q),
        .clock(s1y$2$clock)
    );
    raster_top$fragments$cull_sort$s1z$0 s1z$0(
        .d(s1z$0$d),
        .q(s1z$0$q),
        .clock(s1z$0$clock)
    );
    raster_top$fragments$cull_sort$s1z$1 s1z$1(
        .d(s1z$1$d),
        .q(s1z$1$q),
        .clock(s1z$1$clock)
    );
    raster_top$fragments$cull_sort$s1z$2 s1z$2(
        .d(s1z$2$d),
        .q(s1z$2$q),
        .clock(s1z$2$clock)
    );
    raster_top$fragments$cull_sort$s1c$0 s1c$0(
        .d(s1c$0$d),
        .q(s1c$0$q),
        .clock(s1c$0$clock)
    );
    raster_top$fragments$cull_sort$s1c$1 s1c$1(
        .d(s1c$1$d),
        .q(s1c$1$q),
        .clock(s1c$1$clock)
    );
    raster_top$fragments$cull_sort$s1c$2 s1c$2(
        .d(s1c$2$d),
        .q(s1c$2$q),
        .clock(s1c$2$clock)
    );
    raster_top$fragments$cull_sort$s1c$3 s1c$3(
        .d(s1c$3$d),
        .q(s1c$3$q),
        .clock(s1c$3$clock)
    );
    raster_top$fragments$cull_sort$s1c$4 s1c$4(
        .d(s1c$4$d),
        .q(s1c$4$q),
        .clock(s1c$4$clock)
    );
    raster_top$fragments$cull_sort$s1c$5 s1c$5(
        .d(s1c$5$d),
        .q(s1c$5$q),
        .clock(s1c$5$clock)
    );
    raster_top$fragments$cull_sort$s1c$6 s1c$6(
        .d(s1c$6$d),
        .q(s1c$6$q),
        .clock(s1c$6$clock)
    );
    raster_top$fragments$cull_sort$s1c$7 s1c$7(
        .d(s1c$7$d),
        .q(s1c$7$q),
        .clock(s1c$7$clock)
    );
    raster_top$fragments$cull_sort$s1c$8 s1c$8(
        .d(s1c$8$d),
        .q(s1c$8$q),
        .clock(s1c$8$clock)
    );
    raster_top$fragments$cull_sort$s1iw$0 s1iw$0(
        .d(s1iw$0$d),
        .q(s1iw$0$q),
        .clock(s1iw$0$clock)
    );
    raster_top$fragments$cull_sort$s1iw$1 s1iw$1(
        .d(s1iw$1$d),
        .q(s1iw$1$q),
        .clock(s1iw$1$clock)
    );
    raster_top$fragments$cull_sort$s1iw$2 s1iw$2(
        .d(s1iw$2$d),
        .q(s1iw$2$q),
        .clock(s1iw$2$clock)
    );
    raster_top$fragments$cull_sort$e1x e1x(
        .d(e1x$d),
        .q(e1x$q),
        .clock(e1x$clock)
    );
    raster_top$fragments$cull_sort$e2y e2y(
        .d(e2y$d),
        .q(e2y$q),
        .clock(e2y$clock)
    );
    raster_top$fragments$cull_sort$e2x e2x(
        .d(e2x$d),
        .q(e2x$q),
        .clock(e2x$clock)
    );
    raster_top$fragments$cull_sort$e1y e1y(
        .d(e1y$d),
        .q(e1y$q),
        .clock(e1y$clock)
    );
    raster_top$fragments$cull_sort$outside1 outside1(
        .d(outside1$d),
        .q(outside1$q),
        .clock(outside1$clock)
    );
    raster_top$fragments$cull_sort$crosses1 crosses1(
        .d(crosses1$d),
        .q(crosses1$q),
        .clock(crosses1$clock)
    );
    raster_top$fragments$cull_sort$back1 back1(
        .d(back1$d),
        .q(back1$q),
        .clock(back1$clock)
    );
    raster_top$fragments$cull_sort$full1 full1(
        .d(full1$d),
        .q(full1$q),
        .clock(full1$clock)
    );
    raster_top$fragments$cull_sort$s2x$0 s2x$0(
        .d(s2x$0$d),
        .q(s2x$0$q),
        .clock(s2x$0$clock)
    );
    raster_top$fragments$cull_sort$s2x$1 s2x$1(
        .d(s2x$1$d),
        .q(s2x$1$q),
        .clock(s2x$1$clock)
    );
    raster_top$fragments$cull_sort$s2x$2 s2x$2(
        .d(s2x$2$d),
        .q(s2x$2$q),
        .clock(s2x$2$clock)
    );
    raster_top$fragments$cull_sort$s2y$0 s2y$0(
        .d(s2y$0$d),
        .q(s2y$0$q),
        .clock(s2y$0$clock)
    );
    raster_top$fragments$cull_sort$s2y$1 s2y$1(
        .d(s2y$1$d),
        .q(s2y$1$q),
        .clock(s2y$1$clock)
    );
    raster_top$fragments$cull_sort$s2y$2 s2y$2(
        .d(s2y$2$d),
        .q(s2y$2$q),
        .clock(s2y$2$clock)
    );
    raster_top$fragments$cull_sort$s2z$0 s2z$0(
        .d(s2z$0$d),
        .q(s2z$0$q),
        .clock(s2z$0$clock)
    );
    raster_top$fragments$cull_sort$s2z$1 s2z$1(
        .d(s2z$1$d),
        .q(s2z$1$q),
        .clock(s2z$1$clock)
    );
    raster_top$fragments$cull_sort$s2z$2 s2z$2(
        .d(s2z$2$d),
        .q(s2z$2$q),
        .clock(s2z$2$clock)
    );
    raster_top$fragments$cull_sort$s2c$0 s2c$0(
        .d(s2c$0$d),
        .q(s2c$0$q),
        .clock(s2c$0$clock)
    );
    raster_top$fragments$cull_sort$s2c$1 s2c$1(
        .d(s2c$1$d),
        .q(s2c$1$q),
        .clock(s2c$1$clock)
    );
    raster_top$fragments$cull_sort$s2c$2 s2c$2(
        .d(s2c$2$d),
        .q(s2c$2$q),
        .clock(s2c$2$clock)
    );
    raster_top$fragments$cull_sort$s2c$3 s2c$3(
        .d(s2c$3$d),
        .q(s2c$3$q),
        .clock(s2c$3$clock)
    );
    raster_top$fragments$cull_sort$s2c$4 s2c$4(
        .d(s2c$4$d),
        .q(s2c$4$q),
        .clock(s2c$4$clock)
    );
    raster_top$fragments$cull_sort$s2c$5 s2c$5(
        .d(s2c$5$d),
        .q(s2c$5$q),
        .clock(s2c$5$clock)
    );
    raster_top$fragments$cull_sort$s2c$6 s2c$6(
        .d(s2c$6$d),
        .q(s2c$6$q),
        .clock(s2c$6$clock)
    );
    raster_top$fragments$cull_sort$s2c$7 s2c$7(
        .d(s2c$7$d),
        .q(s2c$7$q),
        .clock(s2c$7$clock)
    );
    raster_top$fragments$cull_sort$s2c$8 s2c$8(
        .d(s2c$8$d),
        .q(s2c$8$q),
        .clock(s2c$8$clock)
    );
    raster_top$fragments$cull_sort$s2iw$0 s2iw$0(
        .d(s2iw$0$d),
        .q(s2iw$0$q),
        .clock(s2iw$0$clock)
    );
    raster_top$fragments$cull_sort$s2iw$1 s2iw$1(
        .d(s2iw$1$d),
        .q(s2iw$1$q),
        .clock(s2iw$1$clock)
    );
    raster_top$fragments$cull_sort$s2iw$2 s2iw$2(
        .d(s2iw$2$d),
        .q(s2iw$2$q),
        .clock(s2iw$2$clock)
    );
    raster_top$fragments$cull_sort$area_mul$0 area_mul$0(
        .a(area_mul$0$a),
        .b(area_mul$0$b),
        .p(area_mul$0$p)
    );
    raster_top$fragments$cull_sort$area_mul$1 area_mul$1(
        .a(area_mul$1$a),
        .b(area_mul$1$b),
        .p(area_mul$1$p)
    );
    raster_top$fragments$cull_sort$prod0 prod0(
        .d(prod0$d),
        .q(prod0$q),
        .clock(prod0$clock)
    );
    raster_top$fragments$cull_sort$prod1 prod1(
        .d(prod1$d),
        .q(prod1$q),
        .clock(prod1$clock)
    );
    raster_top$fragments$cull_sort$outside2 outside2(
        .d(outside2$d),
        .q(outside2$q),
        .clock(outside2$clock)
    );
    raster_top$fragments$cull_sort$crosses2 crosses2(
        .d(crosses2$d),
        .q(crosses2$q),
        .clock(crosses2$clock)
    );
    raster_top$fragments$cull_sort$back2 back2(
        .d(back2$d),
        .q(back2$q),
        .clock(back2$clock)
    );
    raster_top$fragments$cull_sort$full2 full2(
        .d(full2$d),
        .q(full2$q),
        .clock(full2$clock)
    );
    raster_top$fragments$cull_sort$sx$0 sx$0(
        .d(sx$0$d),
        .q(sx$0$q),
        .clock(sx$0$clock)
    );
    raster_top$fragments$cull_sort$sx$1 sx$1(
        .d(sx$1$d),
        .q(sx$1$q),
        .clock(sx$1$clock)
    );
    raster_top$fragments$cull_sort$sx$2 sx$2(
        .d(sx$2$d),
        .q(sx$2$q),
        .clock(sx$2$clock)
    );
    raster_top$fragments$cull_sort$sy$0 sy$0(
        .d(sy$0$d),
        .q(sy$0$q),
        .clock(sy$0$clock)
    );
    raster_top$fragments$cull_sort$sy$1 sy$1(
        .d(sy$1$d),
        .q(sy$1$q),
        .clock(sy$1$clock)
    );
    raster_top$fragments$cull_sort$sy$2 sy$2(
        .d(sy$2$d),
        .q(sy$2$q),
        .clock(sy$2$clock)
    );
    raster_top$fragments$cull_sort$sz$0 sz$0(
        .d(sz$0$d),
        .q(sz$0$q),
        .clock(sz$0$clock)
    );
    raster_top$fragments$cull_sort$sz$1 sz$1(
        .d(sz$1$d),
        .q(sz$1$q),
        .clock(sz$1$clock)
    );
    raster_top$fragments$cull_sort$sz$2 sz$2(
        .d(sz$2$d),
        .q(sz$2$q),
        .clock(sz$2$clock)
    );
    raster_top$fragments$cull_sort$sc$0 sc$0(
        .d(sc$0$d),
        .q(sc$0$q),
        .clock(sc$0$clock)
    );
    raster_top$fragments$cull_sort$sc$1 sc$1(
        .d(sc$1$d),
        .q(sc$1$q),
        .clock(sc$1$clock)
    );
    raster_top$fragments$cull_sort$sc$2 sc$2(
        .d(sc$2$d),
        .q(sc$2$q),
        .clock(sc$2$clock)
    );
    raster_top$fragments$cull_sort$sc$3 sc$3(
        .d(sc$3$d),
        .q(sc$3$q),
        .clock(sc$3$clock)
    );
    raster_top$fragments$cull_sort$sc$4 sc$4(
        .d(sc$4$d),
        .q(sc$4$q),
        .clock(sc$4$clock)
    );
    raster_top$fragments$cull_sort$sc$5 sc$5(
        .d(sc$5$d),
        .q(sc$5$q),
        .clock(sc$5$clock)
    );
    raster_top$fragments$cull_sort$sc$6 sc$6(
        .d(sc$6$d),
        .q(sc$6$q),
        .clock(sc$6$clock)
    );
    raster_top$fragments$cull_sort$sc$7 sc$7(
        .d(sc$7$d),
        .q(sc$7$q),
        .clock(sc$7$clock)
    );
    raster_top$fragments$cull_sort$sc$8 sc$8(
        .d(sc$8$d),
        .q(sc$8$q),
        .clock(sc$8$clock)
    );
    raster_top$fragments$cull_sort$siw$0 siw$0(
        .d(siw$0$d),
        .q(siw$0$q),
        .clock(siw$0$clock)
    );
    raster_top$fragments$cull_sort$siw$1 siw$1(
        .d(siw$1$d),
        .q(siw$1$q),
        .clock(siw$1$clock)
    );
    raster_top$fragments$cull_sort$siw$2 siw$2(
        .d(siw$2$d),
        .q(siw$2$q),
        .clock(siw$2$clock)
    );
    raster_top$fragments$cull_sort$crosses crosses(
        .d(crosses$d),
        .q(crosses$q),
        .clock(crosses$clock)
    );
    raster_top$fragments$cull_sort$code_r code_r(
        .d(code_r$d),
        .q(code_r$q),
        .clock(code_r$clock)
    );
    raster_top$fragments$cull_sort$outside_r outside_r(
        .d(outside_r$d),
        .q(outside_r$q),
        .clock(outside_r$clock)
    );
    raster_top$fragments$cull_sort$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    raster_top$fragments$cull_sort$cull cull(
        .on(cull$on)
    );
    
    // Update code
    always @(*) begin
        e1x$clock = clock;
        e2y$clock = clock;
        e2x$clock = clock;
        e1y$clock = clock;
        outside1$clock = clock;
        crosses1$clock = clock;
        back1$clock = clock;
        full1$clock = clock;
        prod0$clock = clock;
        prod1$clock = clock;
        outside2$clock = clock;
        crosses2$clock = clock;
        back2$clock = clock;
        full2$clock = clock;
        crosses$clock = clock;
        code_r$clock = clock;
        outside_r$clock = clock;
        full$clock = clock;
        e1x$d = e1x$q;
        e2y$d = e2y$q;
        e2x$d = e2x$q;
        e1y$d = e1y$q;
        outside1$d = outside1$q;
        crosses1$d = crosses1$q;
        back1$d = back1$q;
        full1$d = full1$q;
        prod0$d = prod0$q;
        prod1$d = prod1$q;
        outside2$d = outside2$q;
        crosses2$d = crosses2$q;
        back2$d = back2$q;
        full2$d = full2$q;
        crosses$d = crosses$q;
        code_r$d = code_r$q;
        outside_r$d = outside_r$q;
        full$d = full$q;
        s1x$0$clock = clock;
        s1x$0$d = s1x$0$q;
        s1y$0$clock = clock;
        s1y$0$d = s1y$0$q;
        s1z$0$clock = clock;
        s1z$0$d = s1z$0$q;
        s1iw$0$clock = clock;
        s1iw$0$d = s1iw$0$q;
        s2x$0$clock = clock;
        s2x$0$d = s2x$0$q;
        s2y$0$clock = clock;
        s2y$0$d = s2y$0$q;
        s2z$0$clock = clock;
        s2z$0$d = s2z$0$q;
        s2iw$0$clock = clock;
        s2iw$0$d = s2iw$0$q;
        sx$0$clock = clock;
        sx$0$d = sx$0$q;
        sy$0$clock = clock;
        sy$0$d = sy$0$q;
        sz$0$clock = clock;
        sz$0$d = sz$0$q;
        siw$0$clock = clock;
        siw$0$d = siw$0$q;
        s1x$1$clock = clock;
        s1x$1$d = s1x$1$q;
        s1y$1$clock = clock;
        s1y$1$d = s1y$1$q;
        s1z$1$clock = clock;
        s1z$1$d = s1z$1$q;
        s1iw$1$clock = clock;
        s1iw$1$d = s1iw$1$q;
        s2x$1$clock = clock;
        s2x$1$d = s2x$1$q;
        s2y$1$clock = clock;
        s2y$1$d = s2y$1$q;
        s2z$1$clock = clock;
        s2z$1$d = s2z$1$q;
        s2iw$1$clock = clock;
        s2iw$1$d = s2iw$1$q;
        sx$1$clock = clock;
        sx$1$d = sx$1$q;
        sy$1$clock = clock;
        sy$1$d = sy$1$q;
        sz$1$clock = clock;
        sz$1$d = sz$1$q;
        siw$1$clock = clock;
        siw$1$d = siw$1$q;
        s1x$2$clock = clock;
        s1x$2$d = s1x$2$q;
        s1y$2$clock = clock;
        s1y$2$d = s1y$2$q;
        s1z$2$clock = clock;
        s1z$2$d = s1z$2$q;
        s1iw$2$clock = clock;
        s1iw$2$d = s1iw$2$q;
        s2x$2$clock = clock;
        s2x$2$d = s2x$2$q;
        s2y$2$clock = clock;
        s2y$2$d = s2y$2$q;
        s2z$2$clock = clock;
        s2z$2$d = s2z$2$q;
        s2iw$2$clock = clock;
        s2iw$2$d = s2iw$2$q;
        sx$2$clock = clock;
        sx$2$d = sx$2$q;
        sy$2$clock = clock;
        sy$2$d = sy$2$q;
        sz$2$clock = clock;
        sz$2$d = sz$2$q;
        siw$2$clock = clock;
        siw$2$d = siw$2$q;
        s1c$0$clock = clock;
        s1c$0$d = s1c$0$q;
        s2c$0$clock = clock;
        s2c$0$d = s2c$0$q;
        sc$0$clock = clock;
        sc$0$d = sc$0$q;
        s1c$1$clock = clock;
        s1c$1$d = s1c$1$q;
        s2c$1$clock = clock;
        s2c$1$d = s2c$1$q;
        sc$1$clock = clock;
        sc$1$d = sc$1$q;
        s1c$2$clock = clock;
        s1c$2$d = s1c$2$q;
        s2c$2$clock = clock;
        s2c$2$d = s2c$2$q;
        sc$2$clock = clock;
        sc$2$d = sc$2$q;
        s1c$3$clock = clock;
        s1c$3$d = s1c$3$q;
        s2c$3$clock = clock;
        s2c$3$d = s2c$3$q;
        sc$3$clock = clock;
        sc$3$d = sc$3$q;
        s1c$4$clock = clock;
        s1c$4$d = s1c$4$q;
        s2c$4$clock = clock;
        s2c$4$d = s2c$4$q;
        sc$4$clock = clock;
        sc$4$d = sc$4$q;
        s1c$5$clock = clock;
        s1c$5$d = s1c$5$q;
        s2c$5$clock = clock;
        s2c$5$d = s2c$5$q;
        sc$5$clock = clock;
        sc$5$d = sc$5$q;
        s1c$6$clock = clock;
        s1c$6$d = s1c$6$q;
        s2c$6$clock = clock;
        s2c$6$d = s2c$6$q;
        sc$6$clock = clock;
        sc$6$d = sc$6$q;
        s1c$7$clock = clock;
        s1c$7$d = s1c$7$q;
        s2c$7$clock = clock;
        s2c$7$d = s2c$7$q;
        sc$7$clock = clock;
        sc$7$d = sc$7$q;
        s1c$8$clock = clock;
        s1c$8$d = s1c$8$q;
        s2c$8$clock = clock;
        s2c$8$d = s2c$8$q;
        sc$8$clock = clock;
        sc$8$d = sc$8$q;
        vx$0 = inp$v0_x;
        vy$0 = inp$v0_y;
        vz$0 = inp$v0_z;
        vc$0 = inp$v0_c0;
        vc$1 = inp$v0_c1;
        vc$2 = inp$v0_c2;
        viw$0 = inp$v0_iw;
        vx$1 = inp$v1_x;
        vy$1 = inp$v1_y;
        vz$1 = inp$v1_z;
        vc$3 = inp$v1_c0;
        vc$4 = inp$v1_c1;
        vc$5 = inp$v1_c2;
        viw$1 = inp$v1_iw;
        vx$2 = inp$v2_x;
        vy$2 = inp$v2_y;
        vz$2 = inp$v2_z;
        vc$6 = inp$v2_c0;
        vc$7 = inp$v2_c1;
        vc$8 = inp$v2_c2;
        viw$2 = inp$v2_iw;
        out_free = ~full$q | (code_r$q != passed);
        s2_free = ~full2$q | out_free;
        s1_free = ~full1$q | s2_free;
        leave = full$q & ((code_r$q != passed) | out$ready);
        move2 = full2$q & (out_free | out$ready);
        move1 = full1$q & (s2_free | out$ready);
        inp$ready = s1_free | out$ready;
        take = inp$valid & (s1_free | out$ready);
        if (leave) begin
            full$d = 1'b0;
        end
        if (move2) begin
            full2$d = 1'b0;
            full$d = 1'b1;
        end
        if (move1) begin
            full1$d = 1'b0;
            full2$d = 1'b1;
        end
        if (take) begin
            full1$d = 1'b1;
        end
        idle = ~full1$q & ~full2$q & ~(full$q & (code_r$q == passed));
        right = ((width) & 16'hffff) << frac;
        bottom = ((height) & 16'hffff) << frac;
        left$0 = vx$0[xy_msb];
        right_of$0 = ~left$0 & (vx$0 > right);
        top$0 = vy$0[xy_msb];
        below$0 = ~top$0 & (vy$0 > bottom);
        near$0 = vz$0[z_msb];
        far$0 = ~near$0 & (vz$0 > z_max);
        oc$0 = ((((((((32'h0) & 6'h3f) & ~(1 << (32'h0)) | ((left$0) << (32'h0))) & ~(1 << (32'h1)) | ((right_of$0) << (32'h1))) & ~(1 << (32'h2)) | ((top$0) << (32'h2))) & ~(1 << (32'h3)) | ((below$0) << (32'h3))) & ~(1 << (32'h4)) | ((near$0) << (32'h4))) & ~(1 << (32'h5)) | ((far$0) << (32'h5)));
        left$1 = vx$1[xy_msb];
        right_of$1 = ~left$1 & (vx$1 > right);
        top$1 = vy$1[xy_msb];
        below$1 = ~top$1 & (vy$1 > bottom);
        near$1 = vz$1[z_msb];
        far$1 = ~near$1 & (vz$1 > z_max);
        oc$1 = ((((((((32'h0) & 6'h3f) & ~(1 << (32'h0)) | ((left$1) << (32'h0))) & ~(1 << (32'h1)) | ((right_of$1) << (32'h1))) & ~(1 << (32'h2)) | ((top$1) << (32'h2))) & ~(1 << (32'h3)) | ((below$1) << (32'h3))) & ~(1 << (32'h4)) | ((near$1) << (32'h4))) & ~(1 << (32'h5)) | ((far$1) << (32'h5)));
        left$2 = vx$2[xy_msb];
        right_of$2 = ~left$2 & (vx$2 > right);
        top$2 = vy$2[xy_msb];
        below$2 = ~top$2 & (vy$2 > bottom);
        near$2 = vz$2[z_msb];
        far$2 = ~near$2 & (vz$2 > z_max);
        oc$2 = ((((((((32'h0) & 6'h3f) & ~(1 << (32'h0)) | ((left$2) << (32'h0))) & ~(1 << (32'h1)) | ((right_of$2) << (32'h1))) & ~(1 << (32'h2)) | ((top$2) << (32'h2))) & ~(1 << (32'h3)) | ((below$2) << (32'h3))) & ~(1 << (32'h4)) | ((near$2) << (32'h4))) & ~(1 << (32'h5)) | ((far$2) << (32'h5)));
        wx$0$x = vx$0;
        wy$0$x = vy$0;
        wx$1$x = vx$1;
        wy$1$x = vy$1;
        wx$2$x = vx$2;
        wy$2$x = vy$2;
        key$0 = vy$0 ^ half;
        key$1 = vy$1 ^ half;
        key$2 = vy$2 ^ half;
        le01 = key$0 <= key$1;
        le12 = key$1 <= key$2;
        le02 = key$0 <= key$2;
        gt01 = ~le01;
        gt12 = ~le12;
        gt02 = ~le02;
        rank$0 = ((32'h0) & 2'h3) + gt01 + gt02;
        rank$1 = ((32'h0) & 2'h3) + le01 + gt12;
        rank$2 = ((32'h0) & 2'h3) + le02 + le12;
        if (take) begin
            e1x$d = wx$1$y - wx$0$y;
            e2y$d = wy$2$y - wy$0$y;
            e2x$d = wx$2$y - wx$0$y;
            e1y$d = wy$1$y - wy$0$y;
            outside1$d = oc$0 & oc$1 & oc$2;
            crosses1$d = oc$0 | oc$1 | oc$2;
            back1$d = cull_back;
            if (rank$0 == 0) begin
                s1x$0$d = vx$0;
                s1y$0$d = vy$0;
                s1z$0$d = vz$0;
                s1iw$0$d = viw$0;
                s1c$0$d = vc$0;
                s1c$1$d = vc$1;
                s1c$2$d = vc$2;
            end
            if (rank$1 == 0) begin
                s1x$0$d = vx$1;
                s1y$0$d = vy$1;
                s1z$0$d = vz$1;
                s1iw$0$d = viw$1;
                s1c$0$d = vc$3;
                s1c$1$d = vc$4;
                s1c$2$d = vc$5;
            end
            if (rank$2 == 0) begin
                s1x$0$d = vx$2;
                s1y$0$d = vy$2;
                s1z$0$d = vz$2;
                s1iw$0$d = viw$2;
                s1c$0$d = vc$6;
                s1c$1$d = vc$7;
                s1c$2$d = vc$8;
            end
            if (rank$0 == 1) begin
                s1x$1$d = vx$0;
                s1y$1$d = vy$0;
                s1z$1$d = vz$0;
                s1iw$1$d = viw$0;
                s1c$3$d = vc$0;
                s1c$4$d = vc$1;
                s1c$5$d = vc$2;
            end
            if (rank$1 == 1) begin
                s1x$1$d = vx$1;
                s1y$1$d = vy$1;
                s1z$1$d = vz$1;
                s1iw$1$d = viw$1;
                s1c$3$d = vc$3;
                s1c$4$d = vc$4;
                s1c$5$d = vc$5;
            end
            if (rank$2 == 1) begin
                s1x$1$d = vx$2;
                s1y$1$d = vy$2;
                s1z$1$d = vz$2;
                s1iw$1$d = viw$2;
                s1c$3$d = vc$6;
                s1c$4$d = vc$7;
                s1c$5$d = vc$8;
            end
            if (rank$0 == 2) begin
                s1x$2$d = vx$0;
                s1y$2$d = vy$0;
                s1z$2$d = vz$0;
                s1iw$2$d = viw$0;
                s1c$6$d = vc$0;
                s1c$7$d = vc$1;
                s1c$8$d = vc$2;
            end
            if (rank$1 == 2) begin
                s1x$2$d = vx$1;
                s1y$2$d = vy$1;
                s1z$2$d = vz$1;
                s1iw$2$d = viw$1;
                s1c$6$d = vc$3;
                s1c$7$d = vc$4;
                s1c$8$d = vc$5;
            end
            if (rank$2 == 2) begin
                s1x$2$d = vx$2;
                s1y$2$d = vy$2;
                s1z$2$d = vz$2;
                s1iw$2$d = viw$2;
                s1c$6$d = vc$6;
                s1c$7$d = vc$7;
                s1c$8$d = vc$8;
            end
        end
        area_mul$0$a = e1x$q;
        area_mul$0$b = e2y$q;
        area_mul$1$a = e2x$q;
        area_mul$1$b = e1y$q;
        if (move1) begin
            prod0$d = area_mul$0$p;
            prod1$d = area_mul$1$p;
            outside2$d = outside1$q;
            crosses2$d = crosses1$q;
            back2$d = back1$q;
            s2x$0$d = s1x$0$q;
            s2y$0$d = s1y$0$q;
            s2z$0$d = s1z$0$q;
            s2iw$0$d = s1iw$0$q;
            s2x$1$d = s1x$1$q;
            s2y$1$d = s1y$1$q;
            s2z$1$d = s1z$1$q;
            s2iw$1$d = s1iw$1$q;
            s2x$2$d = s1x$2$q;
            s2y$2$d = s1y$2$q;
            s2z$2$d = s1z$2$q;
            s2iw$2$d = s1iw$2$q;
            s2c$0$d = s1c$0$q;
            s2c$1$d = s1c$1$q;
            s2c$2$d = s1c$2$q;
            s2c$3$d = s1c$3$q;
            s2c$4$d = s1c$4$q;
            s2c$5$d = s1c$5$q;
            s2c$6$d = s1c$6$q;
            s2c$7$d = s1c$7$q;
            s2c$8$d = s1c$8$q;
        end
        area = prod0$q - prod1$q;
        code = passed;
        if (cull$on) begin
            if (back2$q & ~area[area_msb]) begin
                code = back_face;
            end
            if (prod0$q == prod1$q) begin
                code = zero_area;
            end
            if (|outside2$q) begin
                code = outside;
            end
        end
        if (move2) begin
            code_r$d = code;
            crosses$d = crosses2$q;
            outside_r$d = outside2$q;
            sx$0$d = s2x$0$q;
            sy$0$d = s2y$0$q;
            sz$0$d = s2z$0$q;
            siw$0$d = s2iw$0$q;
            sx$1$d = s2x$1$q;
            sy$1$d = s2y$1$q;
            sz$1$d = s2z$1$q;
            siw$1$d = s2iw$1$q;
            sx$2$d = s2x$2$q;
            sy$2$d = s2y$2$q;
            sz$2$d = s2z$2$q;
            siw$2$d = s2iw$2$q;
            sc$0$d = s2c$0$q;
            sc$1$d = s2c$1$q;
            sc$2$d = s2c$2$q;
            sc$3$d = s2c$3$q;
            sc$4$d = s2c$4$q;
            sc$5$d = s2c$5$q;
            sc$6$d = s2c$6$q;
            sc$7$d = s2c$7$q;
            sc$8$d = s2c$8$q;
        end
        out$valid = full$q & (code_r$q == passed);
        verdict$valid = leave;
        verdict$code = code_r$q;
        verdict$outside = outside_r$q;
        out$crosses = crosses$q;
        out$v0_x = sx$0$q;
        out$v0_y = sy$0$q;
        out$v0_z = sz$0$q;
        out$v0_c0 = sc$0$q;
        out$v0_c1 = sc$1$q;
        out$v0_c2 = sc$2$q;
        out$v0_iw = siw$0$q;
        out$v1_x = sx$1$q;
        out$v1_y = sy$1$q;
        out$v1_z = sz$1$q;
        out$v1_c0 = sc$3$q;
        out$v1_c1 = sc$4$q;
        out$v1_c2 = sc$5$q;
        out$v1_iw = siw$1$q;
        out$v2_x = sx$2$q;
        out$v2_y = sy$2$q;
        out$v2_z = sz$2$q;
        out$v2_c0 = sc$6$q;
        out$v2_c1 = sc$7$q;
        out$v2_c2 = sc$8$q;
        out$v2_iw = siw$2$q;
    end
    
endmodule // raster_top$fragments$cull_sort


module raster_top$fragments$cull_sort$area_mul$0(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [16:0] b;
    output reg  [33:0] p;
    
    // Update code (custom)
    // p = low 34 bits of a * b, both signed: a signed 34-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // raster_top$fragments$cull_sort$area_mul$0


module raster_top$fragments$cull_sort$area_mul$1(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [16:0] b;
    output reg  [33:0] p;
    
    // Update code (custom)
    // p = low 34 bits of a * b, both signed: a signed 34-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // raster_top$fragments$cull_sort$area_mul$1


module raster_top$fragments$cull_sort$back1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$back1


module raster_top$fragments$cull_sort$back2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$back2


module raster_top$fragments$cull_sort$code_r(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$code_r


module raster_top$fragments$cull_sort$crosses(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$crosses


module raster_top$fragments$cull_sort$crosses1(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$crosses1


module raster_top$fragments$cull_sort$crosses2(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$crosses2


module raster_top$fragments$cull_sort$cull(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // raster_top$fragments$cull_sort$cull


module raster_top$fragments$cull_sort$e1x(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$e1x


module raster_top$fragments$cull_sort$e1y(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$e1y


module raster_top$fragments$cull_sort$e2x(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$e2x


module raster_top$fragments$cull_sort$e2y(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$e2y


module raster_top$fragments$cull_sort$full(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$full


module raster_top$fragments$cull_sort$full1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$full1


module raster_top$fragments$cull_sort$full2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$full2


module raster_top$fragments$cull_sort$outside1(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$outside1


module raster_top$fragments$cull_sort$outside2(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$outside2


module raster_top$fragments$cull_sort$outside_r(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$outside_r


module raster_top$fragments$cull_sort$prod0(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$prod0


module raster_top$fragments$cull_sort$prod1(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$prod1


module raster_top$fragments$cull_sort$s1c$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$0


module raster_top$fragments$cull_sort$s1c$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$1


module raster_top$fragments$cull_sort$s1c$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$2


module raster_top$fragments$cull_sort$s1c$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$3


module raster_top$fragments$cull_sort$s1c$4(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$4


module raster_top$fragments$cull_sort$s1c$5(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$5


module raster_top$fragments$cull_sort$s1c$6(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$6


module raster_top$fragments$cull_sort$s1c$7(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$7


module raster_top$fragments$cull_sort$s1c$8(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1c$8


module raster_top$fragments$cull_sort$s1iw$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1iw$0


module raster_top$fragments$cull_sort$s1iw$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1iw$1


module raster_top$fragments$cull_sort$s1iw$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1iw$2


module raster_top$fragments$cull_sort$s1x$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1x$0


module raster_top$fragments$cull_sort$s1x$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1x$1


module raster_top$fragments$cull_sort$s1x$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1x$2


module raster_top$fragments$cull_sort$s1y$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1y$0


module raster_top$fragments$cull_sort$s1y$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1y$1


module raster_top$fragments$cull_sort$s1y$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1y$2


module raster_top$fragments$cull_sort$s1z$0(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1z$0


module raster_top$fragments$cull_sort$s1z$1(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1z$1


module raster_top$fragments$cull_sort$s1z$2(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s1z$2


module raster_top$fragments$cull_sort$s2c$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$0


module raster_top$fragments$cull_sort$s2c$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$1


module raster_top$fragments$cull_sort$s2c$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$2


module raster_top$fragments$cull_sort$s2c$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$3


module raster_top$fragments$cull_sort$s2c$4(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$4


module raster_top$fragments$cull_sort$s2c$5(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$5


module raster_top$fragments$cull_sort$s2c$6(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$6


module raster_top$fragments$cull_sort$s2c$7(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$7


module raster_top$fragments$cull_sort$s2c$8(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2c$8


module raster_top$fragments$cull_sort$s2iw$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2iw$0


module raster_top$fragments$cull_sort$s2iw$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2iw$1


module raster_top$fragments$cull_sort$s2iw$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2iw$2


module raster_top$fragments$cull_sort$s2x$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2x$0


module raster_top$fragments$cull_sort$s2x$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2x$1


module raster_top$fragments$cull_sort$s2x$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2x$2


module raster_top$fragments$cull_sort$s2y$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2y$0


module raster_top$fragments$cull_sort$s2y$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2y$1


module raster_top$fragments$cull_sort$s2y$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2y$2


module raster_top$fragments$cull_sort$s2z$0(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2z$0


module raster_top$fragments$cull_sort$s2z$1(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2z$1


module raster_top$fragments$cull_sort$s2z$2(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$s2z$2


module raster_top$fragments$cull_sort$sc$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$0


module raster_top$fragments$cull_sort$sc$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$1


module raster_top$fragments$cull_sort$sc$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$2


module raster_top$fragments$cull_sort$sc$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$3


module raster_top$fragments$cull_sort$sc$4(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$4


module raster_top$fragments$cull_sort$sc$5(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$5


module raster_top$fragments$cull_sort$sc$6(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$6


module raster_top$fragments$cull_sort$sc$7(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$7


module raster_top$fragments$cull_sort$sc$8(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sc$8


module raster_top$fragments$cull_sort$siw$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$siw$0


module raster_top$fragments$cull_sort$siw$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$siw$1


module raster_top$fragments$cull_sort$siw$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$siw$2


module raster_top$fragments$cull_sort$sx$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sx$0


module raster_top$fragments$cull_sort$sx$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sx$1


module raster_top$fragments$cull_sort$sx$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sx$2


module raster_top$fragments$cull_sort$sy$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sy$0


module raster_top$fragments$cull_sort$sy$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sy$1


module raster_top$fragments$cull_sort$sy$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sy$2


module raster_top$fragments$cull_sort$sz$0(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sz$0


module raster_top$fragments$cull_sort$sz$1(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sz$1


module raster_top$fragments$cull_sort$sz$2(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$cull_sort$sz$2


module raster_top$fragments$cull_sort$wx$0(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // raster_top$fragments$cull_sort$wx$0


module raster_top$fragments$cull_sort$wx$1(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // raster_top$fragments$cull_sort$wx$1


module raster_top$fragments$cull_sort$wx$2(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // raster_top$fragments$cull_sort$wx$2


module raster_top$fragments$cull_sort$wy$0(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // raster_top$fragments$cull_sort$wy$0


module raster_top$fragments$cull_sort$wy$1(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // raster_top$fragments$cull_sort$wy$1


module raster_top$fragments$cull_sort$wy$2(x,y);
    
    // Module arguments
    input wire  [15:0] x;
    output reg  [16:0] y;
    
    // Constant declarations
    localparam  msb = 8'hf;
    localparam  ext = 17'b10000000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 17'h1ffff);
        if (x[msb]) begin
            y = ((x) & 17'h1ffff) | ext;
        end
    end
    
endmodule // raster_top$fragments$cull_sort$wy$2


module raster_top$fragments$last_in(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$fragments$last_in


module raster_top$pixel_out(clock,inp$valid,inp$ready,inp$x,inp$y,inp$z,inp$rgb0,inp$rgb1,inp$rgb2,mem$ready,mem$rd_en,mem$rd_addr,mem$rd_z,mem$wr_en,mem$wr_addr,mem$wr_z,mem$wr_rgb,idle);
    
    // Module arguments
    input wire  clock;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$x;
    input wire  [9:0] inp$y;
    input wire  [15:0] inp$z;
    input wire  [7:0] inp$rgb0;
    input wire  [7:0] inp$rgb1;
    input wire  [7:0] inp$rgb2;
    input wire  mem$ready;
    output wire  mem$rd_en;
    output wire  [19:0] mem$rd_addr;
    input wire  [15:0] mem$rd_z;
    output wire  mem$wr_en;
    output wire  [19:0] mem$wr_addr;
    output wire  [15:0] mem$wr_z;
    output wire  [23:0] mem$wr_rgb;
    output reg  idle;
    
    // Constant declarations
    localparam  one = 1'b1;
    
    // Stub signals
    reg  chunk$clock;
    reg  chunk$in_valid;
    wire  chunk$in_ready;
    reg  chunk$in_mask;
    reg  [19:0] chunk$in_addr;
    reg  [15:0] chunk$in_z;
    reg  [23:0] chunk$in_rgb;
    wire  chunk$idle;
    reg  [9:0] addr$hi;
    reg  [9:0] addr$lo;
    wire  [19:0] addr$out;
    reg  [7:0] rg$hi;
    reg  [7:0] rg$lo;
    wire  [15:0] rg$out;
    reg  [15:0] rgb$hi;
    reg  [7:0] rgb$lo;
    wire  [23:0] rgb$out;
    
    // Sub module instances
    raster_top$pixel_out$chunk chunk(
        .clock(chunk$clock),
        .in_valid(chunk$in_valid),
        .in_ready(chunk$in_ready),
        .in_mask(chunk$in_mask),
        .in_addr(chunk$in_addr),
        .in_z(chunk$in_z),
        .in_rgb(chunk$in_rgb),
        .mem$ready(mem$ready),
        .mem$rd_en(mem$rd_en),
        .mem$rd_addr(mem$rd_addr),
        .mem$rd_z(mem$rd_z),
        .mem$wr_en(mem$wr_en),
        .mem$wr_addr(mem$wr_addr),
        .mem$wr_z(mem$wr_z),
        .mem$wr_rgb(mem$wr_rgb),
        .idle(chunk$idle)
    );
    raster_top$pixel_out$addr addr(
        .hi(addr$hi),
        .lo(addr$lo),
        .out(addr$out)
    );
    raster_top$pixel_out$rg rg(
        .hi(rg$hi),
        .lo(rg$lo),
        .out(rg$out)
    );
    raster_top$pixel_out$rgb rgb(
        .hi(rgb$hi),
        .lo(rgb$lo),
        .out(rgb$out)
    );
    
    // Update code
    always @(*) begin
        chunk$clock = clock;
        addr$hi = inp$y;
        addr$lo = inp$x;
        rg$hi = inp$rgb0;
        rg$lo = inp$rgb1;
        rgb$hi = rg$out;
        rgb$lo = inp$rgb2;
        chunk$in_valid = inp$valid;
        chunk$in_mask = one;
        chunk$in_addr = addr$out;
        chunk$in_z = inp$z;
        chunk$in_rgb = rgb$out;
        inp$ready = chunk$in_ready;
        idle = chunk$idle;
    end
    
endmodule // raster_top$pixel_out


module raster_top$pixel_out$addr(hi,lo,out);
    
    // Module arguments
    input wire  [9:0] hi;
    input wire  [9:0] lo;
    output reg  [19:0] out;
    
    // Constant declarations
    localparam  shift = 8'ha;
    
    // Update code
    always @(*) begin
        out = (((hi) & 20'hfffff) << shift) | ((lo) & 20'hfffff);
    end
    
endmodule // raster_top$pixel_out$addr


module raster_top$pixel_out$chunk(clock,in_valid,in_ready,in_mask,in_addr,in_z,in_rgb,mem$ready,mem$rd_en,mem$rd_addr,mem$rd_z,mem$wr_en,mem$wr_addr,mem$wr_z,mem$wr_rgb,idle);
    
    // Module arguments
    input wire  clock;
    input wire  in_valid;
    output reg  in_ready;
    input wire  in_mask;
    input wire  [19:0] in_addr;
    input wire  [15:0] in_z;
    input wire  [23:0] in_rgb;
    input wire  mem$ready;
    output reg  mem$rd_en;
    output reg  [19:0] mem$rd_addr;
    input wire  [15:0] mem$rd_z;
    output reg  mem$wr_en;
    output reg  [19:0] mem$wr_addr;
    output reg  [15:0] mem$wr_z;
    output reg  [23:0] mem$wr_rgb;
    output reg  idle;
    
    // Stub signals
    wire  depth_test$on;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_mask$d;
    wire  s1_mask$q;
    reg  s1_mask$clock;
    reg  [19:0] s1_addr$d;
    wire  [19:0] s1_addr$q;
    reg  s1_addr$clock;
    reg  [15:0] s1_z$d;
    wire  [15:0] s1_z$q;
    reg  s1_z$clock;
    reg  [23:0] s1_rgb$d;
    wire  [23:0] s1_rgb$q;
    reg  s1_rgb$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_write$d;
    wire  s2_write$q;
    reg  s2_write$clock;
    reg  [19:0] s2_addr$d;
    wire  [19:0] s2_addr$q;
    reg  s2_addr$clock;
    reg  [15:0] s2_z$d;
    wire  [15:0] s2_z$q;
    reg  s2_z$clock;
    reg  [23:0] s2_rgb$d;
    wire  [23:0] s2_rgb$q;
    reg  s2_rgb$clock;
    reg  s3_write$d;
    wire  s3_write$q;
    reg  s3_write$clock;
    reg  [15:0] s3_z$d;
    wire  [15:0] s3_z$q;
    reg  s3_z$clock;
    reg  hit2$d;
    wire  hit2$q;
    reg  hit2$clock;
    reg  hit3$d;
    wire  hit3$q;
    reg  hit3$clock;
    reg  [15:0] lanes$0$rd_z;
    reg  [15:0] lanes$0$s1_z;
    reg  [15:0] lanes$0$s2_z;
    reg  [15:0] lanes$0$s3_z;
    reg  lanes$0$s1_mask;
    reg  lanes$0$s2_write;
    reg  lanes$0$s3_write;
    reg  lanes$0$hit2;
    reg  lanes$0$hit3;
    reg  lanes$0$on;
    wire  lanes$0$pass;
    
    // Local signals
    reg  g_pass$0;
    reg  g_pass$1;
    reg  pass;
    
    // Sub module instances
    raster_top$pixel_out$chunk$depth_test depth_test(
        .on(depth_test$on)
    );
    raster_top$pixel_out$chunk$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    raster_top$pixel_out$chunk$s1_mask s1_mask(
        .d(s1_mask$d),
        .q(s1_mask$q),
        .clock(s1_mask$clock)
    );
    raster_top$pixel_out$chunk$s1_addr s1_addr(
        .d(s1_addr$d),
        .q(s1_addr$q),
        .clock(s1_addr$clock)
    );
    raster_top$pixel_out$chunk$s1_z s1_z(
        .d(s1_z$d),
        .q(s1_z$q),
        .clock(s1_z$clock)
    );
    raster_top$pixel_out$chunk$s1_rgb s1_rgb(
        .d(s1_rgb$d),
        .q(s1_rgb$q),
        .clock(s1_rgb$clock)
    );
    raster_top$pixel_out$chunk$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    raster_top$pixel_out$chunk$s2_write s2_write(
        .d(s2_write$d),
        .q(s2_write$q),
        .clock(s2_write$clock)
    );
    raster_top$pixel_out$chunk$s2_addr s2_addr(
        .d(s2_addr$d),
        .q(s2_addr$q),
        .clock(s2_addr$clock)
    );
    raster_top$pixel_out$chunk$s2_z s2_z(
        .d(s2_z$d),
        .q(s2_z$q),
        .clock(s2_z$clock)
    );
    raster_top$pixel_out$chunk$s2_rgb s2_rgb(
        .d(s2_rgb$d),
        .q(s2_rgb$q),
        .clock(s2_rgb$clock)
    );
    raster_top$pixel_out$chunk$s3_write s3_write(
        .d(s3_write$d),
        .q(s3_write$q),
        .clock(s3_write$clock)
    );
    raster_top$pixel_out$chunk$s3_z s3_z(
        .d(s3_z$d),
        .q(s3_z$q),
        .clock(s3_z$clock)
    );
    raster_top$pixel_out$chunk$hit2 hit2(
        .d(hit2$d),
        .q(hit2$q),
        .clock(hit2$clock)
    );
    raster_top$pixel_out$chunk$hit3 hit3(
        .d(hit3$d),
        .q(hit3$q),
        .clock(hit3$clock)
    );
    raster_top$pixel_out$chunk$lanes$0 lanes$0(
        .rd_z(lanes$0$rd_z),
        .s1_z(lanes$0$s1_z),
        .s2_z(lanes$0$s2_z),
        .s3_z(lanes$0$s3_z),
        .s1_mask(lanes$0$s1_mask),
        .s2_write(lanes$0$s2_write),
        .s3_write(lanes$0$s3_write),
        .hit2(lanes$0$hit2),
        .hit3(lanes$0$hit3),
        .on(lanes$0$on),
        .pass(lanes$0$pass)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_mask$clock = clock;
        s1_addr$clock = clock;
        s1_z$clock = clock;
        s1_rgb$clock = clock;
        s2_valid$clock = clock;
        s2_write$clock = clock;
        s2_addr$clock = clock;
        s2_z$clock = clock;
        s2_rgb$clock = clock;
        s3_write$clock = clock;
        s3_z$clock = clock;
        hit2$clock = clock;
        hit3$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_mask$d = s1_mask$q;
        s1_addr$d = s1_addr$q;
        s1_z$d = s1_z$q;
        s1_rgb$d = s1_rgb$q;
        s2_valid$d = s2_valid$q;
        s2_write$d = s2_write$q;
        s2_addr$d = s2_addr$q;
        s2_z$d = s2_z$q;
        s2_rgb$d = s2_rgb$q;
        s3_write$d = s3_write$q;
        s3_z$d = s3_z$q;
        hit2$d = hit2$q;
        hit3$d = hit3$q;
        in_ready = mem$ready;
        mem$rd_en = 32'h0;
        if (in_valid & depth_test$on) begin
            mem$rd_en = in_mask;
        end
        mem$rd_addr = in_addr;
        g_pass$0 = 32'h0;
        lanes$0$rd_z = mem$rd_z;
        lanes$0$s1_z = s1_z$q;
        lanes$0$s2_z = s2_z$q;
        lanes$0$s3_z = s3_z$q;
        lanes$0$s1_mask = s1_mask$q;
        lanes$0$s2_write = s2_write$q;
        lanes$0$s3_write = s3_write$q;
        lanes$0$hit2 = hit2$q;
        lanes$0$hit3 = hit3$q;
        lanes$0$on = depth_test$on;
        g_pass$1 = g_pass$0 | lanes$0$pass;
        pass = g_pass$1;
        mem$wr_en = s2_write$q;
        mem$wr_addr = s2_addr$q;
        mem$wr_z = s2_z$q;
        mem$wr_rgb = s2_rgb$q;
        idle = ~s1_valid$q & ~s2_valid$q;
        if (mem$ready) begin
            s1_valid$d = in_valid;
            s1_mask$d = 32'h0;
            if (in_valid) begin
                s1_mask$d = in_mask;
            end
            s1_addr$d = in_addr;
            s1_z$d = in_z;
            s1_rgb$d = in_rgb;
            hit2$d = s1_addr$q == in_addr;
            hit3$d = s2_addr$q == in_addr;
            s2_valid$d = s1_valid$q;
            s2_write$d = pass;
            s2_addr$d = s1_addr$q;
            s2_z$d = s1_z$q;
            s2_rgb$d = s1_rgb$q;
            s3_write$d = s2_write$q;
            s3_z$d = s2_z$q;
        end
    end
    
endmodule // raster_top$pixel_out$chunk


module raster_top$pixel_out$chunk$depth_test(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // raster_top$pixel_out$chunk$depth_test


module raster_top$pixel_out$chunk$hit2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$hit2


module raster_top$pixel_out$chunk$hit3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$hit3


module raster_top$pixel_out$chunk$lanes$0(rd_z,s1_z,s2_z,s3_z,s1_mask,s2_write,s3_write,hit2,hit3,on,pass);
    
    // Module arguments
    input wire  [15:0] rd_z;
    input wire  [15:0] s1_z;
    input wire  [15:0] s2_z;
    input wire  [15:0] s3_z;
    input wire  s1_mask;
    input wire  s2_write;
    input wire  s3_write;
    input wire  hit2;
    input wire  hit3;
    input wire  on;
    output reg  pass;
    
    // Constant declarations
    localparam  at = 16'h0;
    localparam  lane_bit = 1'b1;
    
    // Local signals
    reg  [15:0] z;
    reg  [15:0] old_z;
    
    // Update code
    always @(*) begin
        old_z = ((rd_z >> at) & 16'hffff);
        if (((s3_write & lane_bit) != 32'h0) & hit3) begin
            old_z = ((s3_z >> at) & 16'hffff);
        end
        if (((s2_write & lane_bit) != 32'h0) & hit2) begin
            old_z = ((s2_z >> at) & 16'hffff);
        end
        z = ((s1_z >> at) & 16'hffff);
        pass = s1_mask & lane_bit;
        if (on & (z >= old_z)) begin
            pass = 32'h0;
        end
    end
    
endmodule // raster_top$pixel_out$chunk$lanes$0


module raster_top$pixel_out$chunk$s1_addr(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s1_addr


module raster_top$pixel_out$chunk$s1_mask(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s1_mask


module raster_top$pixel_out$chunk$s1_rgb(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s1_rgb


module raster_top$pixel_out$chunk$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s1_valid


module raster_top$pixel_out$chunk$s1_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s1_z


module raster_top$pixel_out$chunk$s2_addr(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s2_addr


module raster_top$pixel_out$chunk$s2_rgb(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s2_rgb


module raster_top$pixel_out$chunk$s2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s2_valid


module raster_top$pixel_out$chunk$s2_write(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s2_write


module raster_top$pixel_out$chunk$s2_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s2_z


module raster_top$pixel_out$chunk$s3_write(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s3_write


module raster_top$pixel_out$chunk$s3_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // raster_top$pixel_out$chunk$s3_z


module raster_top$pixel_out$rg(hi,lo,out);
    
    // Module arguments
    input wire  [7:0] hi;
    input wire  [7:0] lo;
    output reg  [15:0] out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    
    // Update code
    always @(*) begin
        out = (((hi) & 16'hffff) << shift) | ((lo) & 16'hffff);
    end
    
endmodule // raster_top$pixel_out$rg


module raster_top$pixel_out$rgb(hi,lo,out);
    
    // Module arguments
    input wire  [15:0] hi;
    input wire  [7:0] lo;
    output reg  [23:0] out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    
    // Update code
    always @(*) begin
        out = (((hi) & 24'hffffff) << shift) | ((lo) & 24'hffffff);
    end
    
endmodule // raster_top$pixel_out$rgb
